#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cosim {

namespace hdf5 {
class OutputFile;
class InputFile;
}  // namespace hdf5

// A solver's state on disk, the part of a coupled checkpoint it writes
// (architecture.md §14): named arrays and numbers in one HDF5 file that
// says which kind of state it holds and in which format version.
//
//   StateFileWriter out(dir / "state.h5", "swe_solver_1d", 1);
//   out.numbers("depth", h);
//   out.rows("position", particles.position);   // fixed-size Eigen rows
//   out.number("time", t);
//   out.commit();                                // renamed into place
//
//   const StateFileReader in(dir / "state.h5", "swe_solver_1d", 1);
//   in.numbers("depth", h.size(), h);            // exactly that many, bit for bit
//
// The file is written aside and renamed by commit(), so one that exists is
// complete; a writer destroyed before commit() leaves nothing. A reader
// refuses, with an Error (exit 2) naming the file and the array, another
// kind or version, a missing array, an array of another length, or a file
// HDF5 cannot read (truncated, not HDF5).
class StateFileWriter {
 public:
  StateFileWriter(std::filesystem::path file, std::string_view kind, std::int64_t version);
  ~StateFileWriter();
  StateFileWriter(const StateFileWriter&) = delete;
  StateFileWriter& operator=(const StateFileWriter&) = delete;

  void numbers(const std::string& name, std::span<const double> values);
  void integers(const std::string& name, std::span<const std::int64_t> values);
  void number(const std::string& name, double value);
  void integer(const std::string& name, std::int64_t value);

  // Arrays of fixed-size Eigen vectors or matrices (or std::array<double,
  // N>), stored as rows of their N numbers.
  template <class Row>
  void rows(const std::string& name, const std::vector<Row>& values) {
    constexpr std::size_t width = sizeof(Row) / sizeof(double);
    static_assert(sizeof(Row) == width * sizeof(double), "rows of doubles only");
    numbers_with_width(
        name, {reinterpret_cast<const double*>(values.data()), values.size() * width}, width);
  }

  void commit();

 private:
  void numbers_with_width(const std::string& name, std::span<const double> values,
                          std::size_t width);

  std::filesystem::path file_;
  std::filesystem::path staged_;
  std::unique_ptr<hdf5::OutputFile> out_;
};

class StateFileReader {
 public:
  StateFileReader(const std::filesystem::path& file, std::string_view kind, std::int64_t version);
  ~StateFileReader();
  StateFileReader(const StateFileReader&) = delete;
  StateFileReader& operator=(const StateFileReader&) = delete;

  bool has(const std::string& name) const;
  // The array `name`, which must hold `count` values.
  void numbers(const std::string& name, std::size_t count, std::vector<double>& values) const;
  void integers(const std::string& name, std::size_t count,
                std::vector<std::int64_t>& values) const;
  // An array of any length.
  std::vector<double> numbers(const std::string& name) const;
  std::vector<std::int64_t> integers(const std::string& name) const;
  double number(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;

  // `count` rows written by StateFileWriter::rows.
  template <class Row>
  void rows(const std::string& name, std::size_t count, std::vector<Row>& values) const {
    constexpr std::size_t width = sizeof(Row) / sizeof(double);
    static_assert(sizeof(Row) == width * sizeof(double), "rows of doubles only");
    const std::vector<double> flat = rows_with_width(name, count, width);
    values.resize(count);
    if (count > 0) std::memcpy(static_cast<void*>(values.data()), flat.data(), count * sizeof(Row));
  }

  const std::filesystem::path& file() const { return file_; }

 private:
  std::vector<double> rows_with_width(const std::string& name, std::size_t count,
                                      std::size_t width) const;
  [[noreturn]] void refuse(const std::string& name, const std::string& what) const;

  std::filesystem::path file_;
  std::unique_ptr<hdf5::InputFile> in_;
};

}  // namespace cosim

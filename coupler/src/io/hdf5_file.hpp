#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// Thin RAII layer over the HDF5 C API for the snapshot writer: every handle
// closes itself, every failure becomes cosim::Error with HDF5's own message.
namespace cosim::hdf5 {

// Switches off HDF5's printing of its error stack to stderr for the calling
// thread; failures are reported through exceptions instead.
void silence_error_printing();

// Throws Error "HDF5: <what>: <messages of the HDF5 error stack>" and clears the stack.
[[noreturn]] void fail(const std::string& what);

template <herr_t (*Close)(hid_t)>
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, const std::string& what) : id_(id) {
    if (id_ < 0) fail(what);
  }
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  // Closes now and reports a failure (a file's close flushes its data).
  void close(const std::string& what) {
    const hid_t id = std::exchange(id_, H5I_INVALID_HID);
    if (id >= 0 && Close(id) < 0) fail(what);
  }

 private:
  void reset() {
    if (id_ >= 0) Close(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
};

using FileHandle = Handle<H5Fclose>;
using DatasetHandle = Handle<H5Dclose>;
using DataspaceHandle = Handle<H5Sclose>;
using DatatypeHandle = Handle<H5Tclose>;
using AttributeHandle = Handle<H5Aclose>;
using PropertyListHandle = Handle<H5Pclose>;
using GroupHandle = Handle<H5Gclose>;

// A new HDF5 file (an existing one is truncated) to which datasets and
// attributes are added by path; intermediate groups are created as needed.
class OutputFile {
 public:
  // `access`: the file access properties (H5P_DEFAULT, or MPI-IO for a file
  // every rank of a decomposed run writes together).
  explicit OutputFile(const std::filesystem::path& path, hid_t access = H5P_DEFAULT);

  void write(const std::string& dataset, std::span<const hsize_t> dims,
             std::span<const double> values, std::string_view unit = {});
  // This process's part of a dataset of `dims`: the block of `count` values
  // per dimension from `start` (slowest first), written with the transfer
  // properties `transfer` (collective MPI-IO in a decomposed run, where
  // every rank calls this in the same order).
  struct Part {
    std::span<const hsize_t> start, count;
    hid_t transfer = H5P_DEFAULT;
  };
  void write(const std::string& dataset, std::span<const hsize_t> dims, const Part& part,
             std::span<const double> values, std::string_view unit = {});
  void write(const std::string& dataset, std::span<const hsize_t> dims,
             std::span<const std::int64_t> values);
  // This process's rows of a dataset of `dims` (rows along the first
  // dimension): `runs` holds (first row, rows) pairs in increasing order,
  // the values are those rows one after the other; written with `transfer`
  // (collective in a decomposed run, where a process may hold no row).
  struct Rows {
    std::span<const hsize_t> runs;
    hid_t transfer = H5P_DEFAULT;
  };
  void write(const std::string& dataset, std::span<const hsize_t> dims, const Rows& rows,
             std::span<const double> values, std::string_view unit = {});
  void write(const std::string& dataset, std::span<const hsize_t> dims, const Rows& rows,
             std::span<const std::int64_t> values);
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, std::int64_t value);
  void set_attribute(const std::string& name, std::string_view value);
  // Closes and flushes the file; throws if that fails.
  void close();

 private:
  // The groups of a dataset's path that do not exist yet, without times.
  void create_groups_above(const std::string& dataset, const std::string& where);
  void write_raw(const std::string& dataset, std::span<const hsize_t> dims, hid_t file_type,
                 hid_t memory_type, const void* values, std::size_t count, std::string_view unit,
                 const Part* part = nullptr, const Rows* rows = nullptr);
  void set_scalar_attribute(hid_t object, const std::string& name, hid_t file_type,
                            hid_t memory_type, const void* value);

  std::string path_;
  FileHandle file_;
};

// An HDF5 file opened to read; every failure (no such file or dataset, a
// truncated file, another type) is an Error naming the file and the dataset.
class InputFile {
 public:
  explicit InputFile(const std::filesystem::path& path);

  bool has(const std::string& dataset) const;
  std::vector<hsize_t> dims(const std::string& dataset) const;
  std::vector<double> read_doubles(const std::string& dataset) const;
  std::vector<std::int64_t> read_integers(const std::string& dataset) const;
  // The file's own attributes; nullopt-free: a missing one is an Error.
  std::string string_attribute(const std::string& name) const;
  std::int64_t integer_attribute(const std::string& name) const;

  const std::string& path() const { return path_; }

 private:
  void read_raw(const std::string& dataset, hid_t memory_type, void* values,
                std::size_t count) const;

  std::string path_;
  FileHandle file_;
};

}  // namespace cosim::hdf5

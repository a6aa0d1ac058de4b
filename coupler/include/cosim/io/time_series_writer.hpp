#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace cosim {

// A CSV time series (probes, gauges): one header row of column names with
// their SI units (`time [s]`, `eta_gauge1 [m]`), then one row per append with
// every value at full double precision (`{:.17g}`, round-trips exactly).
// Each row reaches the operating system in a single write() on a file opened
// O_APPEND, so a process that dies keeps every row appended before, and no
// row is ever half-written by this writer.
class TimeSeriesWriter {
 public:
  enum class Mode {
    replace,  // start a new file (a new run)
    append,   // continue an existing file whose header matches (a restart)
  };

  // Throws InputError when a column name is empty or contains a comma, quote
  // or line break, or (append) the existing header differs; Error when the
  // file cannot be opened.
  TimeSeriesWriter(std::filesystem::path path, std::vector<std::string> columns,
                   Mode mode = Mode::replace);
  ~TimeSeriesWriter();
  TimeSeriesWriter(TimeSeriesWriter&& other) noexcept;
  TimeSeriesWriter& operator=(TimeSeriesWriter&& other) noexcept;
  TimeSeriesWriter(const TimeSeriesWriter&) = delete;
  TimeSeriesWriter& operator=(const TimeSeriesWriter&) = delete;

  // One value per column; throws InputError on a count mismatch.
  void append(std::span<const double> row);
  void append(std::initializer_list<double> row) { append(std::span(row.begin(), row.size())); }

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows_written() const { return rows_; }

 private:
  void write_all(const std::string& text);

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  int fd_ = -1;
  std::size_t rows_ = 0;
};

// Column name with its unit in the conventional form: `name [unit]`.
std::string column_name(const std::string& name, const std::string& unit);

}  // namespace cosim

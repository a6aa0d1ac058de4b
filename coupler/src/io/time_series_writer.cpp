#include "cosim/io/time_series_writer.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <utility>

#include "cosim/error.hpp"

namespace cosim {

namespace {

std::string header_line(const std::vector<std::string>& columns) {
  return fmt::format("{}\n", fmt::join(columns, ","));
}

void check_columns(const std::filesystem::path& path, const std::vector<std::string>& columns) {
  if (columns.empty()) throw InputError("time series '" + path.string() + "' has no columns");
  for (const std::string& c : columns)
    if (c.empty() || c.find_first_of(",\"\r\n") != std::string::npos)
      throw InputError("time series '" + path.string() + "': column name '" + c +
                       "' is empty or contains a comma, quote or line break");
}

std::string first_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

std::string column_name(const std::string& name, const std::string& unit) {
  return fmt::format("{} [{}]", name, unit);
}

TimeSeriesWriter::TimeSeriesWriter(std::filesystem::path path, std::vector<std::string> columns,
                                   Mode mode)
    : path_(std::move(path)), columns_(std::move(columns)) {
  check_columns(path_, columns_);
  const std::string header = header_line(columns_);
  bool write_header = true;
  int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC;
  if (mode == Mode::append && std::filesystem::exists(path_) &&
      std::filesystem::file_size(path_) > 0) {
    const std::string existing = first_line(path_);
    if (existing + "\n" != header)
      throw InputError("time series '" + path_.string() + "': existing header '" + existing +
                       "' differs from '" + header.substr(0, header.size() - 1) + "'");
    write_header = false;
  } else {
    flags |= O_TRUNC;
  }
  fd_ = ::open(path_.c_str(), flags, 0644);
  if (fd_ < 0)
    throw Error(ExitCode::bad_input,
                "cannot open time series '" + path_.string() + "': " + std::strerror(errno));
  if (write_header) write_all(header);
}

TimeSeriesWriter::~TimeSeriesWriter() {
  if (fd_ >= 0) ::close(fd_);
}

TimeSeriesWriter::TimeSeriesWriter(TimeSeriesWriter&& other) noexcept
    : path_(std::move(other.path_)),
      columns_(std::move(other.columns_)),
      fd_(std::exchange(other.fd_, -1)),
      rows_(other.rows_) {}

TimeSeriesWriter& TimeSeriesWriter::operator=(TimeSeriesWriter&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    columns_ = std::move(other.columns_);
    fd_ = std::exchange(other.fd_, -1);
    rows_ = other.rows_;
  }
  return *this;
}

void TimeSeriesWriter::append(std::span<const double> row) {
  if (row.size() != columns_.size())
    throw InputError(fmt::format("time series '{}': row of {} values for {} columns",
                                 path_.string(), row.size(), columns_.size()));
  fmt::memory_buffer line;
  for (std::size_t c = 0; c < row.size(); ++c)
    fmt::format_to(std::back_inserter(line), "{}{:.17g}", c == 0 ? "" : ",", row[c]);
  line.push_back('\n');
  write_all(fmt::to_string(line));
  ++rows_;
}

void TimeSeriesWriter::write_all(const std::string& text) {
  if (fd_ < 0) throw Error(ExitCode::bad_input, "time series '" + path_.string() + "' is closed");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw Error(ExitCode::bad_input,
                  "cannot write time series '" + path_.string() + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace cosim

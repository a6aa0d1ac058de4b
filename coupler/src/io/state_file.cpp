#include "cosim/io/state_file.hpp"

#include <fmt/format.h>

#include <system_error>
#include <utility>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "hdf5_file.hpp"

namespace cosim {

namespace {

constexpr const char* kind_attribute = "state_kind";
constexpr const char* version_attribute = "state_format_version";

std::string array_path(const std::string& name) {
  return "state/" + name;
}

}  // namespace

StateFileWriter::StateFileWriter(std::filesystem::path file, std::string_view kind,
                                 std::int64_t version)
    : file_(std::move(file)), staged_(staging_path(file_)) {
  hdf5::silence_error_printing();
  out_ = std::make_unique<hdf5::OutputFile>(staged_);
  out_->set_attribute(kind_attribute, kind);
  out_->set_attribute(version_attribute, version);
}

StateFileWriter::~StateFileWriter() {
  if (!out_) return;
  out_.reset();
  std::error_code ignored;
  std::filesystem::remove(staged_, ignored);
}

void StateFileWriter::numbers(const std::string& name, std::span<const double> values) {
  const hsize_t dims[] = {values.size()};
  out_->write(array_path(name), dims, values);
}

void StateFileWriter::integers(const std::string& name, std::span<const std::int64_t> values) {
  const hsize_t dims[] = {values.size()};
  out_->write(array_path(name), dims, values);
}

void StateFileWriter::number(const std::string& name, double value) {
  numbers(name, {&value, 1});
}

void StateFileWriter::integer(const std::string& name, std::int64_t value) {
  integers(name, {&value, 1});
}

void StateFileWriter::numbers_with_width(const std::string& name, std::span<const double> values,
                                         std::size_t width) {
  const hsize_t dims[] = {values.size() / width, width};
  out_->write(array_path(name), dims, values);
}

void StateFileWriter::commit() {
  out_->close();
  out_.reset();
  commit_staged_file(staged_, file_);
}

StateFileReader::StateFileReader(const std::filesystem::path& file, std::string_view kind,
                                 std::int64_t version)
    : file_(file) {
  hdf5::silence_error_printing();
  if (!std::filesystem::is_regular_file(file_))
    throw Error(ExitCode::bad_input, fmt::format("state file '{}' does not exist", file_.string()));
  in_ = std::make_unique<hdf5::InputFile>(file_);
  const std::string found_kind = in_->string_attribute(kind_attribute);
  if (found_kind != kind)
    throw Error(ExitCode::bad_input,
                fmt::format("state file '{}' holds the state of a {}, not of a {}", file_.string(),
                            found_kind, kind));
  const std::int64_t found_version = in_->integer_attribute(version_attribute);
  if (found_version != version)
    throw Error(ExitCode::bad_input,
                fmt::format("state file '{}' is in format version {} of a {}'s state; this "
                            "program reads version {}",
                            file_.string(), found_version, kind, version));
}

StateFileReader::~StateFileReader() = default;

bool StateFileReader::has(const std::string& name) const {
  return in_->has("state") && in_->has(array_path(name));
}

void StateFileReader::refuse(const std::string& name, const std::string& what) const {
  throw Error(ExitCode::bad_input,
              fmt::format("state file '{}': array '{}' {}", file_.string(), name, what));
}

void StateFileReader::numbers(const std::string& name, std::size_t count,
                              std::vector<double>& values) const {
  values = numbers(name);
  if (values.size() != count)
    refuse(name, fmt::format("holds {} values where {} are expected", values.size(), count));
}

void StateFileReader::integers(const std::string& name, std::size_t count,
                               std::vector<std::int64_t>& values) const {
  values = integers(name);
  if (values.size() != count)
    refuse(name, fmt::format("holds {} values where {} are expected", values.size(), count));
}

std::vector<double> StateFileReader::numbers(const std::string& name) const {
  if (!has(name)) refuse(name, "is missing");
  return in_->read_doubles(array_path(name));
}

std::vector<std::int64_t> StateFileReader::integers(const std::string& name) const {
  if (!has(name)) refuse(name, "is missing");
  return in_->read_integers(array_path(name));
}

double StateFileReader::number(const std::string& name) const {
  std::vector<double> value;
  numbers(name, 1, value);
  return value[0];
}

std::int64_t StateFileReader::integer(const std::string& name) const {
  std::vector<std::int64_t> value;
  integers(name, 1, value);
  return value[0];
}

std::vector<double> StateFileReader::rows_with_width(const std::string& name, std::size_t count,
                                                     std::size_t width) const {
  if (!has(name)) refuse(name, "is missing");
  const std::vector<hsize_t> dims = in_->dims(array_path(name));
  if (dims.size() != 2 || dims[1] != width || dims[0] != count)
    refuse(name, fmt::format("is not {} rows of {} numbers", count, width));
  return in_->read_doubles(array_path(name));
}

}  // namespace cosim

#include "exchange/drag_parameters.hpp"

#include <cmath>
#include <utility>

namespace cosim::exchange {

DragParameters::DragParameters(YAML::Node node, std::string key_path, std::string file)
    : node_(std::move(node)), key_path_(std::move(key_path)), file_(std::move(file)) {}

std::string DragParameters::path_of(const std::string& key) const {
  return key_path_.empty() ? key : key_path_ + "." + key;
}

SourceLocation DragParameters::location_of(const YAML::Node& node) const {
  const YAML::Mark mark = node.Mark();
  if (mark.line < 0) return {file_, 0, 0};
  return {file_, mark.line + 1, mark.column + 1};
}

void DragParameters::fail(const std::string& key, const std::string& what) const {
  const YAML::Node& map = node_;
  const YAML::Node value = map[key];
  throw InputError(location_of(value.IsDefined() ? value : map), path_of(key), what);
}

bool DragParameters::has(const std::string& key) const {
  const YAML::Node& map = node_;
  return map[key].IsDefined() && !map[key].IsNull();
}

bool DragParameters::is_per_cell(const std::string& key) {
  const YAML::Node& map = node_;
  const YAML::Node value = map[key];
  if (!value.IsDefined() || !value.IsScalar() || value.Scalar() != "field") return false;
  read_.insert(key);
  return true;
}

std::string DragParameters::word(const std::string& key) {
  read_.insert(key);
  const YAML::Node& map = node_;
  const YAML::Node value = map[key];
  if (!value.IsDefined() || !value.IsScalar() || value.Scalar().empty()) {
    fail(key, "missing (a name is required)");
  }
  return value.Scalar();
}

std::optional<double> DragParameters::optional_positive(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return positive(key);
}

double DragParameters::positive(const std::string& key) {
  read_.insert(key);
  const YAML::Node& map = node_;
  const YAML::Node value = map[key];
  if (!value.IsDefined() || value.IsNull()) fail(key, "missing (a number > 0 is required)");
  double number = 0;
  try {
    number = value.as<double>();
  } catch (const YAML::Exception&) {
    fail(key,
         "expected a number, got '" + (value.IsScalar() ? value.Scalar() : "<not a scalar>") + "'");
  }
  if (!std::isfinite(number) || number <= 0) {
    fail(key, "must be a finite number > 0, got " + value.Scalar());
  }
  return number;
}

void DragParameters::finish() const {
  for (const auto& entry : node_) {
    const auto key = entry.first.as<std::string>();
    if (!read_.contains(key)) {
      throw InputError(location_of(entry.first), path_of(key),
                       "unknown key for drag law '" + node_["law"].as<std::string>("?") + "'");
    }
  }
}

}  // namespace cosim::exchange

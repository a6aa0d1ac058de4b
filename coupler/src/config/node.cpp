#include "cosim/config/node.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace cosim::config {

SourceLocation location_in(const SourceFile& source, const YAML::Mark& mark) {
  if (mark.line < 0) return {source.name.string(), 0, 0};
  return {source.name.string(), mark.line + 1, mark.column + 1};
}

namespace {

template <class T>
std::optional<T> converted(const YAML::Node& yaml) {
  try {
    return yaml.as<T>();
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

// A number written as 1e6 or 2.0 is a whole number too.
std::optional<std::int64_t> whole_number(const YAML::Node& yaml) {
  if (auto exact = converted<std::int64_t>(yaml)) return exact;
  auto real = converted<double>(yaml);
  if (!real || std::trunc(*real) != *real) return std::nullopt;
  constexpr double limit = 9.2e18;
  if (std::abs(*real) > limit) return std::nullopt;
  return static_cast<std::int64_t>(*real);
}

template <class T>
std::vector<T> list_of(const Node& node) {
  std::vector<T> values;
  for (const Node& item : node.items()) values.push_back(item.as<T>());
  return values;
}

}  // namespace

Node::Node(YAML::Node yaml, std::shared_ptr<const SourceFile> source, std::string key_path,
           YAML::Mark key_mark)
    : yaml_(std::move(yaml)),
      source_(std::move(source)),
      key_path_(std::move(key_path)),
      key_mark_(key_mark) {}

Node Node::child(const YAML::Node& value, const YAML::Node& key) const {
  const std::string& name = key.Scalar();
  return Node(value, source_, key_path_.empty() ? name : key_path_ + "." + name, key.Mark());
}

std::optional<Node> Node::find(std::string_view key) const {
  if (!is_map()) return std::nullopt;
  for (auto it = yaml_.begin(); it != yaml_.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key) return child(it->second, it->first);
  }
  return std::nullopt;
}

bool Node::has(std::string_view key) const {
  return find(key).has_value();
}

Node Node::operator[](std::string_view key) const {
  if (!is_map()) fail(fmt::format("expected a mapping with key '{}', got {}", key, describe()));
  if (auto found = find(key)) return *found;
  const std::string missing_path =
      key_path_.empty() ? std::string(key) : fmt::format("{}.{}", key_path_, key);
  throw InputError(location(), missing_path, fmt::format("missing required key '{}'", key));
}

std::vector<std::pair<std::string, Node>> Node::entries() const {
  if (!is_map()) fail(fmt::format("expected a mapping, got {}", describe()));
  std::vector<std::pair<std::string, Node>> result;
  for (auto it = yaml_.begin(); it != yaml_.end(); ++it) {
    result.emplace_back(it->first.Scalar(), child(it->second, it->first));
  }
  return result;
}

std::vector<Node> Node::items() const {
  if (!is_sequence()) fail(fmt::format("expected a list, got {}", describe()));
  std::vector<Node> result;
  result.reserve(yaml_.size());
  for (std::size_t i = 0; i < yaml_.size(); ++i) {
    const YAML::Node item = yaml_[i];
    result.emplace_back(item, source_, fmt::format("{}[{}]", key_path_, i), item.Mark());
  }
  return result;
}

SourceLocation Node::location() const {
  // A null value (`key:` with nothing after it) has no position of its own.
  if (yaml_.IsNull() || yaml_.Mark().line < 0) return key_location();
  return location_in(*source_, yaml_.Mark());
}

SourceLocation Node::key_location() const {
  if (key_mark_.line < 0) return location_in(*source_, yaml_.Mark());
  return location_in(*source_, key_mark_);
}

void Node::fail(const std::string& what) const {
  throw InputError(location(), key_path_, what);
}

void Node::fail_at_key(const std::string& what) const {
  throw InputError(key_location(), key_path_, what);
}

std::string Node::describe() const {
  switch (yaml_.Type()) {
    case YAML::NodeType::Scalar:
      return fmt::format("'{}'", yaml_.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      break;
  }
  return "no value";
}

std::filesystem::path Node::as_path() const {
  const std::string text = as<std::string>();
  if (text.empty()) fail("expected a path, got an empty string");
  std::filesystem::path path(text);
  if (path.is_relative()) path = source_->directory / path;
  return path.lexically_normal();
}

template <>
std::string Node::as<std::string>() const {
  if (!is_scalar()) fail(fmt::format("expected a string, got {}", describe()));
  return yaml_.Scalar();
}

template <>
double Node::as<double>() const {
  if (!is_scalar()) fail(fmt::format("expected a number, got {}", describe()));
  auto value = converted<double>(yaml_);
  if (!value) fail(fmt::format("expected a number, got {}", describe()));
  if (!std::isfinite(*value)) fail(fmt::format("expected a finite number, got {}", describe()));
  return *value;
}

template <>
std::int64_t Node::as<std::int64_t>() const {
  if (!is_scalar()) fail(fmt::format("expected a whole number, got {}", describe()));
  auto value = whole_number(yaml_);
  if (!value) fail(fmt::format("expected a whole number, got {}", describe()));
  return *value;
}

template <>
int Node::as<int>() const {
  const std::int64_t value = as<std::int64_t>();
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
    fail(fmt::format("{} is out of range for this setting", value));
  }
  return static_cast<int>(value);
}

template <>
std::size_t Node::as<std::size_t>() const {
  const std::int64_t value = as<std::int64_t>();
  if (value < 0) fail(fmt::format("must not be negative, got {}", value));
  return static_cast<std::size_t>(value);
}

template <>
bool Node::as<bool>() const {
  if (!is_scalar()) fail(fmt::format("expected true or false, got {}", describe()));
  auto value = converted<bool>(yaml_);
  if (!value) fail(fmt::format("expected true or false, got {}", describe()));
  return *value;
}

template <>
std::vector<double> Node::as<std::vector<double>>() const {
  return list_of<double>(*this);
}

template <>
std::vector<int> Node::as<std::vector<int>>() const {
  return list_of<int>(*this);
}

template <>
std::vector<std::string> Node::as<std::vector<std::string>>() const {
  return list_of<std::string>(*this);
}

}  // namespace cosim::config

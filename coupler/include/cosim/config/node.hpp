#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::config {

// The file a node was read from: its name as the user gave it (used in
// messages) and the absolute directory its relative paths resolve from.
struct SourceFile {
  std::filesystem::path name;
  std::filesystem::path directory;
};

// A yaml-cpp position (0-based, -1 when unknown) as a 1-based SourceLocation
// in `source` (line 0 when unknown).
SourceLocation location_in(const SourceFile& source, const YAML::Mark& mark);

// A YAML node that knows where it came from: its file, its position and its
// key path (`participants.soil.config`, `exchange[1].field`). Every accessor
// that cannot give what was asked for throws an InputError located at the
// node, so callers never see a bare yaml-cpp exception.
class Node {
 public:
  Node(YAML::Node yaml, std::shared_ptr<const SourceFile> source, std::string key_path,
       YAML::Mark key_mark);

  bool is_map() const { return yaml_.IsMap(); }
  bool is_sequence() const { return yaml_.IsSequence(); }
  bool is_scalar() const { return yaml_.IsScalar(); }
  bool is_null() const { return yaml_.IsNull(); }

  // Mapping access. `operator[]` throws, located at this mapping, when the
  // key is missing; `has`/`find` are for optional keys.
  bool has(std::string_view key) const;
  std::optional<Node> find(std::string_view key) const;
  Node operator[](std::string_view key) const;

  // The scalar (or list) converted to T. Supported: double, int,
  // std::int64_t, std::size_t, bool, std::string, std::vector<double>,
  // std::vector<int>, std::vector<std::string>. Numbers must be finite;
  // std::size_t refuses negatives.
  template <class T>
  T as() const {
    static_assert(sizeof(T) == 0, "Node::as<T>: T is not one of the supported types");
  }

  // `as<T>()` of the key, which must be present: a required key, or an
  // optional one the schema's add_defaults has filled in.
  template <class T>
  T get(std::string_view key) const {
    return (*this)[key].template as<T>();
  }

  // `as<T>()` of the key when present, `fallback` when absent.
  template <class T>
  T get(std::string_view key, T fallback) const {
    auto child = find(key);
    return child ? child->template as<T>() : fallback;
  }
  std::string get(std::string_view key, const char* fallback) const {
    return get<std::string>(key, fallback);
  }

  // A string scalar taken as a path: relative paths resolve from the
  // directory of the file this node was read from.
  std::filesystem::path as_path() const;

  // Mapping entries in file order, and sequence items.
  std::vector<std::pair<std::string, Node>> entries() const;
  std::vector<Node> items() const;
  std::size_t size() const { return yaml_.size(); }

  const std::string& key_path() const { return key_path_; }
  // Where the value starts; and where the key naming it starts (the value's
  // own location for the root and sequence items).
  SourceLocation location() const;
  SourceLocation key_location() const;
  const SourceFile& source() const { return *source_; }

  // Throw an InputError located at the value / at its key.
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void fail_at_key(const std::string& what) const;

  // The scalar text as written, for messages ("got 'abc'").
  std::string describe() const;

  const YAML::Node& yaml() const { return yaml_; }

 private:
  Node child(const YAML::Node& value, const YAML::Node& key) const;

  YAML::Node yaml_;
  std::shared_ptr<const SourceFile> source_;
  std::string key_path_;
  YAML::Mark key_mark_;
};

template <>
double Node::as<double>() const;
template <>
int Node::as<int>() const;
template <>
std::int64_t Node::as<std::int64_t>() const;
template <>
std::size_t Node::as<std::size_t>() const;
template <>
bool Node::as<bool>() const;
template <>
std::string Node::as<std::string>() const;
template <>
std::vector<double> Node::as<std::vector<double>>() const;
template <>
std::vector<int> Node::as<std::vector<int>>() const;
template <>
std::vector<std::string> Node::as<std::vector<std::string>>() const;

}  // namespace cosim::config

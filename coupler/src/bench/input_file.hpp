#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "bench/suite.hpp"

namespace cosim::bench {

// One YAML input of a bench run, read from the suite's configs, changed by
// the suite's overrides and written into the run's own directory. Relative
// paths in it are made absolute on reading, so the copy means what the
// original meant wherever it is written; the files they name are remembered
// (their contents are part of the run's key).
class InputFile {
 public:
  // Throws InputError naming the file when it cannot be read or parsed.
  static InputFile read(const std::filesystem::path& file);
  static InputFile from_node(YAML::Node root, std::string role_name);

  // Puts `o.value` at `o.key_path`, creating missing mapping keys; a
  // sequence index must exist. Throws InputError at the override's location.
  void apply(const Override& o);
  void apply_all(const std::vector<Override>& overrides, const std::string& role);

  YAML::Node& root() { return root_; }
  const YAML::Node& root() const { return root_; }
  const std::filesystem::path& source() const { return source_; }
  const std::set<std::filesystem::path>& referenced_files() const { return referenced_; }

  // The YAML text (block style); written atomically to `path`.
  std::string text() const;
  void write(const std::filesystem::path& path) const;

 private:
  void absolutize(YAML::Node node, const std::string& key);

  std::filesystem::path source_;
  YAML::Node root_;
  std::set<std::filesystem::path> referenced_;
};

// A scalar read from a YAML tree by dotted key path, or `fallback`.
std::string scalar_at(const YAML::Node& root, const std::string& key_path,
                      const std::string& fallback = {});

}  // namespace cosim::bench

#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <set>
#include <string>

#include "cosim/error.hpp"

namespace cosim::exchange {

// Reads the parameters of one drag law from its YAML map and reports every
// problem as cosim::InputError naming the full key path and its line/column.
// Each key read is remembered; finish() rejects the keys nobody read (typos).
class DragParameters {
 public:
  DragParameters(YAML::Node node, std::string key_path, std::string file);

  // A finite number > 0.
  double positive(const std::string& key);
  std::optional<double> optional_positive(const std::string& key);
  // A non-empty scalar word.
  std::string word(const std::string& key);
  bool has(const std::string& key) const;
  // True when the key holds the word `field`: the value comes per cell from
  // the exchanged field of that name instead of the config.
  bool is_per_cell(const std::string& key);

  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  void finish() const;

  const std::string& key_path() const { return key_path_; }

 private:
  std::string path_of(const std::string& key) const;
  SourceLocation location_of(const YAML::Node& node) const;

  YAML::Node node_;
  std::string key_path_;
  std::string file_;
  std::set<std::string> read_;
};

}  // namespace cosim::exchange

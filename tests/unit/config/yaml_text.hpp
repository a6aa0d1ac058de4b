#pragma once

#include <string>
#include <vector>

// YAML files written line by line in the config tests, and where a token stands in a line.
namespace cosim::config::testing {

// The 1-based column of `token` in `line` (0 when absent).
inline int column_of(const std::string& line, const std::string& token) {
  const auto at = line.find(token);
  return at == std::string::npos ? 0 : static_cast<int>(at) + 1;
}

// `lines` joined with newlines, each line a line of the YAML file.
inline std::string yaml_text(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) text += line + '\n';
  return text;
}

}  // namespace cosim::config::testing

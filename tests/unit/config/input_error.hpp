#pragma once

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::config::testing {

// The InputError `action` throws, printed so the test log shows what a user
// would read; a test failure when nothing is thrown.
template <class Action>
InputError input_error_from(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    std::cout << "    InputError: " << error.what() << '\n';
    return error;
  }
  ADD_FAILURE() << "expected an InputError, nothing was thrown";
  return InputError("nothing was thrown");
}

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

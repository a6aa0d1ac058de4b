#pragma once

#include <gtest/gtest.h>

#include <string>

namespace cosim::testing {

// `text` with its first `from` replaced by `to`, for tests that break one
// key of a good config; a `from` that is not there fails the test.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace cosim::testing

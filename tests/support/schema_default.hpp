#pragma once

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "cosim/config/schema.hpp"

namespace cosim::testing {

// The default a schema states for `key_path` ("numerics.cfl", "materials.<name>.viscosity",
// "output.gauges.[].name"), read as T; a test failure when the key has none.
template <class T>
T schema_default(const config::Schema& schema, const std::string& key_path) {
  const std::string text = schema.default_of(key_path);
  EXPECT_FALSE(text.empty()) << key_path << " has no default";
  return YAML::Load(text).as<T>();
}

}  // namespace cosim::testing

#pragma once

#include <string>

#include "cosim/config/node.hpp"

namespace cosim::config {

// Every cosim YAML file says what it is (`kind: job`, `kind: mpm_case`).
// Throws an InputError when the root is not a mapping, has no `kind`, or
// names another kind ("this is a 'mpm_case' file, but a 'job' file is
// expected here").
void expect_kind(const Node& root, const std::string& kind);

}  // namespace cosim::config

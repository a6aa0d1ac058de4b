#pragma once

#include <string>

#include "cosim/config/schema.hpp"

namespace mpm {

// The keys of a `kind: mpm_case` file: the one place they are documented.
// Materials are listed as `materials.<name>` mappings whose keys each
// constitutive model declares in the MaterialRegistry.
cosim::config::Schema mpm_case_schema();

// `mpm_solver --help-config`: the case keys, then every material model's.
std::string mpm_case_help();

}  // namespace mpm

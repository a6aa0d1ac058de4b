#pragma once

#include <string>

#include "cosim/config/schema.hpp"

namespace ice {

// Every key of a `kind: ice_case` file, for validation and --help-config
// (which also lists the equations of state).
cosim::config::Schema ice_case_schema();
std::string ice_case_help();

}  // namespace ice

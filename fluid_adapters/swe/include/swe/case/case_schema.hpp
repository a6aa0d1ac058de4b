#pragma once

#include <string>

#include "cosim/config/schema.hpp"

namespace swe {

// Every key of a `kind: swe_case` file, for validation and --help-config.
cosim::config::Schema swe_case_schema();
std::string swe_case_help();

}  // namespace swe

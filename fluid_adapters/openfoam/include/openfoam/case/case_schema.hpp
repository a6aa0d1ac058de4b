#pragma once

#include <string>

#include "cosim/config/schema.hpp"

namespace openfoam {

// Every key of a `kind: openfoam_case` file, for validation and --help-config.
cosim::config::Schema openfoam_case_schema();
std::string openfoam_case_help();

}  // namespace openfoam

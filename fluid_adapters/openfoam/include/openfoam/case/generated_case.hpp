#pragma once

#include <filesystem>

#include "openfoam/case/case_description.hpp"

namespace openfoam {

// Writes the complete OpenFOAM case of `c` into `case_dir` (created): the
// block mesh, the water regions for setFields, the fluids, gravity, laminar
// flow, the VOF solver's schemes and solution controls, and the initial
// fields 0/alpha.water, 0/U, 0/p_rgh with the sides' conditions. The
// controlDict is written by the run (write_control_dict) before each start.
void write_generated_case(const GeneratedCase& c, const std::filesystem::path& case_dir);

// The patch names of the generated mesh, per side (x_min, x_max, ... z_max).
const char* side_patch_name(int side);

}  // namespace openfoam

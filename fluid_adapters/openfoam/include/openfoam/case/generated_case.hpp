#pragma once

#include <filesystem>

#include "openfoam/case/case_description.hpp"

namespace openfoam {

// Writes the complete OpenFOAM case of `c` into `case_dir` (created): the
// block mesh, the water regions for setFields, the fluids, gravity, laminar
// flow, the VOF solver's schemes and solution controls, and the initial
// fields 0/alpha.water, 0/U, 0/p_rgh with the sides' conditions. The
// controlDict is written by the run (write_control_dict) before each start.
// With `cloud` (MPPICInterFoam) also constant/kinematicCloudProperties: the
// soil's parcels (soil_cloud.hpp) with Ergun-Wen-Yu drag and nothing else (no
// gravity on them, no injection, packing, damping or collisions).
void write_generated_case(const GeneratedCase& c, const std::filesystem::path& case_dir,
                          const SoilSettings* cloud = nullptr);

// The kinematicCloudProperties of the soil's parcels (also what a user's
// MPPICInterFoam case is checked against).
std::string soil_cloud_properties(const SoilSettings& cloud);

// The patch names of the generated mesh, per side (x_min, x_max, ... z_max).
const char* side_patch_name(int side);

}  // namespace openfoam

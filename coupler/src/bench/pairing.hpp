#pragma once

#include <string>

#include "bench/input_file.hpp"
#include "bench/suite.hpp"

// A pairing: the MPM soil coupled to one fluid backend. It knows which
// fields cross in each direction, on which meshes, with which mapping, and
// who solves the drag, so a scenario writes its soil and its coupling once
// and each backend only its fluid case (architecture.md §4):
//   ice, openfoam  porous soil in a fluid: the soil sends solid_fraction,
//                  solid_velocity and solid_bulk_density (and permeability or
//                  grain_size when the drag law reads them per cell), the
//                  fluid solves the drag in its own steps (`solved_by:
//                  fluid`) and returns pore_pressure and the impulse the
//                  soil receives (ice: also pore_pressure_force);
//   swe            a seabed under shallow water: bed_elevation up,
//                  bed_traction down (Zheng et al., Algorithm 1).
namespace cosim::bench {

// The participants' names in a paired job (and their output directories).
inline constexpr const char* fluid_participant = "water";
inline constexpr const char* soil_participant = "soil";

struct PairedJob {
  InputFile job;
  InputFile soil;   // the soil's case with its coupling block for this pairing
  InputFile fluid;  // the fluid's case with its coupling block for this pairing
};

// `soil` and `fluid` as read (overrides applied); the job refers to them
// as `soil_file` and `fluid_file`. Throws InputError (located at the
// scenario) when the pairing cannot be built, e.g. a porous pairing without
// a drag law.
PairedJob make_paired_job(Backend backend, const Scenario& scenario, InputFile soil,
                          InputFile fluid, const std::string& job_name,
                          const std::string& soil_file, const std::string& fluid_file);

}  // namespace cosim::bench

#pragma once

#include <string>

#include "bench/input_file.hpp"
#include "bench/suite.hpp"

// A pairing: the MPM soil coupled to one fluid backend. Which fields cross in
// each direction, on which meshes, with which mapping, who solves the drag and
// which keys each case gets are data of the two backends' descriptors (the
// fluid's `fluid_pairing`, the soil's `soil_pairings` of the same kind,
// backend_descriptor.hpp); this builds the job from them, so a scenario writes
// its soil and its coupling once and each backend only its fluid case
// (architecture.md §4).
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
PairedJob make_paired_job(const BackendDescriptor& fluid_backend, const Scenario& scenario,
                          InputFile soil, InputFile fluid, const std::string& job_name,
                          const std::string& soil_file, const std::string& fluid_file);

}  // namespace cosim::bench

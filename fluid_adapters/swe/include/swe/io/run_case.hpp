#pragma once

#include <filesystem>

#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/participant.hpp"

namespace swe {

struct RunOptions {
  std::filesystem::path config;
  std::filesystem::path output;
  int threads = -1;  // -1: the case's `threads`
  cosim::Verbosity verbosity = cosim::Verbosity::normal;
  cosim::OutputReuse reuse = cosim::OutputReuse::refuse;  // a non-empty `output`
};

// Runs a swe_case, standalone (empty endpoint) or as a participant of a
// coupled job, and writes into options.output (architecture.md §6; a directory
// holding an earlier run is refused, nothing written, unless options.reuse
// says otherwise):
//   summary.json, log.txt
//   swe.xdmf + swe_<k>.h5   snapshots of h, eta, B, discharge, velocity
//   gauges.csv              eta, h and speed at the case's gauges
//   water.csv               per snapshot: volume, highest/lowest wet free
//                           surface, fastest water
// Coupled, it reads `bed_elevation` on its cells (mesh `swe_cells`) every
// step and writes `bed_traction` at the end of every window; the pair's step
// is min(stable SWE step, the window's remainder) (Zheng et al., eq. 38,
// with the MPM's own step inside the MPM process). Windows can be repeated
// (implicit coupling; standalone, --cosim-repeat-windows with the case's
// time.window): the solver's state and the run's progress are copied at a
// window's start and restored when it runs again, and the outputs due inside
// it are held in memory until it is complete (wall time in the summary's
// phases save_state and restore_state). Returns the exit code.
int run_case(const RunOptions& options, const cosim::CouplingEndpoint& endpoint);

}  // namespace swe

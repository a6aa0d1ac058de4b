#pragma once

#include <filesystem>

#include "cosim/io/logging.hpp"
#include "cosim/participant.hpp"

namespace ice {

struct RunOptions {
  std::filesystem::path config;
  std::filesystem::path output;
  int threads = -1;  // -1: the case's `threads`
  cosim::Verbosity verbosity = cosim::Verbosity::normal;
};

// Runs an ice_case and writes into options.output (DESIGN.md §6):
//   summary.json   conserved totals per material (mass, momentum, total
//                  energy) at start and end, steps, wall time by phase,
//                  metrics (CG iterations, smallest step, rejected steps)
//   log.txt
//   ice.xdmf + ice_<k>.h5   snapshots (see SnapshotFieldSet)
//   gauges.csv              pressure, velocity, volume fractions at points
//   steps.csv               per snapshot: time, dt, CG iterations, most
//                           equilibration iterations, volume closure
// Returns the exit code.
int run_case(const RunOptions& options, const cosim::CouplingEndpoint& endpoint);

}  // namespace ice

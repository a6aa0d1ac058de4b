#pragma once

#include "cosim/solver_command_line.hpp"

namespace ice {

// Runs the ice_case of line.config, standalone or as a participant of a
// coupled job (line.endpoint), and writes into line.output (architecture.md §6;
// prepared as line.reuse says: a directory holding an earlier run is
// refused, nothing written, unless overwritten):
//   summary.json   conserved totals per material (mass, momentum, total
//                  energy) at start and end, steps, wall time by phase,
//                  metrics (CG iterations, smallest step, rejected steps)
//   log.txt
//   ice.xdmf + ice_<k>.h5   snapshots (see SnapshotFieldSet)
//   gauges.csv              pressure, velocity, volume fractions at points
//   steps.csv               per snapshot: time, dt, CG iterations, most
//                           equilibration iterations, volume closure
// Windows may run again (implicit coupling, --cosim-repeat-windows): the
// solver and the run's bookkeeping are saved at each window's start and
// restored when it repeats; its outputs are written once it completes.
// Returns the exit code.
int run_case(const cosim::SolverCommandLine& line);

}  // namespace ice

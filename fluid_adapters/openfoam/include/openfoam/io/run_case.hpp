#pragma once

#include "cosim/solver_command_line.hpp"

namespace openfoam {

// openfoam_adapter's run: reads the case, makes or checks the OpenFOAM case
// in <output>/case, then runs the solver window after window (restarting it
// from its latest time directory), reading its fields back for the
// snapshots and summary.json (with each window's write, start-up, stepping
// and read times). Returns the exit code (architecture.md §6).
int run_case(const cosim::SolverCommandLine& options);

}  // namespace openfoam

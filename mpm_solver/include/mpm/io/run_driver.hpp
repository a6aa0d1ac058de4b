#pragma once

#include <filesystem>

#include "cosim/exit_codes.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "mpm/io/step_observer.hpp"

namespace mpm {

struct RunOptions {
  std::filesystem::path config;      // the case file (kind: mpm_case)
  std::filesystem::path output;      // run directory
  int threads = -1;                  // OpenMP threads; < 0: the case's `threads`
  int check_every = 100;             // check_state() interval in steps (and at every output)
  double progress_interval_s = 5.0;  // wall time between progress lines in the log
  cosim::Verbosity verbosity = cosim::Verbosity::normal;  // console; log.txt keeps info
  cosim::OutputReuse reuse = cosim::OutputReuse::refuse;  // a non-empty `output`
};

// A standalone (or, with an observer, coupled) run of one case, as
// architecture.md §6: prepares <output> (options.reuse: a directory holding an
// earlier run is refused before anything is written, unless overwritten),
// sets up <output>/log.txt, loads the case, runs Solver<2|3>
// to the end time writing particle snapshots (particles.xdmf), grid
// snapshots (grid.xdmf, with output.grid), probes.csv, and summary.json,
// which is finished with the exit code and message on every path. Returns
// the process exit code: 0, 2 bad input, 4 numerical failure, 1 internal
// error (or the code of any other cosim::Error); a refused output directory
// throws its cosim::Error instead, nothing written.
// An observer that repeats windows (step_observer.hpp) has the solver's
// state and the loop's saved at each window's start and restored for a
// repeat; outputs inside such a window are written once it is complete.
int run_case(const RunOptions& options, const StepObservers& observers = {});

// The same run, standalone, by each rank mpirun started (issue 27): the grid
// cut into slabs of cell rows, one per rank, the points migrating between
// them, and the files of a run on one process (particle snapshots written
// by all ranks together; summary.json by rank 0; rank r's log and summary
// in <output>/ranks/rank_<r>/). The totals in the summary are summed over
// the ranks (equal to round-off). Cases with heat conduction or grid
// snapshots are refused (exit 2). The observers (standalone coupling
// windows) run on every rank. Without MPI in the build, run_case.
int run_decomposed_case(const RunOptions& options, const StepObservers& observers = {});

// A coupled participant of an MPMD job (transport mpi://): on one rank
// run_case; on N > 1 ranks (`ranks: N` in the job) the decomposed run above
// on this program's ranks, every rank a part of the participant
// (mpm::coupling declares its part of the exchange grid).
int run_mpi_participant(const RunOptions& options, const StepObservers& observers);
// Whether mpirun started this process as one of several ranks (false
// without MPI in the build).
bool started_on_several_ranks();

}  // namespace mpm

#pragma once

#include <cstddef>
#include <string>

// `cosim run <job.yaml> --output <dir>`: starts the job's participants,
// couples them until the end time, and leaves the run directory complete
// whatever happens (summary.json finished, log lines kept, no process left).
namespace cosim::app {

// The connect timeout's range [s]: long enough for a slow start, short
// enough that a deadline computed from it cannot overflow.
inline constexpr double min_connect_timeout_s = 0.1;
inline constexpr double max_connect_timeout_s = 1.0e6;

struct RunOptions {
  std::string job_file;
  std::string output;
  std::string job_id;  // set by the MPI launch; a fresh one otherwise
  std::string verbosity = "normal";
  bool print_mpi_command = false;
  // Write a Slurm batch script of the MPI job to this file (and its srun
  // multi-prog configuration next to it) instead of running it.
  std::string slurm_script;
  // clear the earlier run a non-empty --output holds; with --slurm-script,
  // replace an existing script
  bool overwrite = false;
  double connect_timeout_s = 120.0;
  std::string checkpoint_every;  // empty: no checkpoints
  std::size_t checkpoints_kept = 2;
  std::string restart;  // a checkpoint directory to continue from
};

// Returns the process exit code (architecture.md §6).
int run_job(const RunOptions& options);

}  // namespace cosim::app

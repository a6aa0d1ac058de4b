#pragma once

#include <filesystem>
#include <string>

#include "run_process.hpp"

// The demo job of configs/demo (two test participants on different grids)
// with options, for the tests of `cosim run`.
namespace cosim::testing {

struct JobOptions {
  std::string transport = "zmq";
  std::string extrapolation = "constant";
  std::string scheme = "ipc";
  std::string host = "127.0.0.1";
  std::string name = "e2e";
  double end_time = 0.05;
  double window_timeout = 60.0;
  std::string left_args = "[]";
  std::string right_args = "[]";
  int left_ranks = 1;  // MPI ranks of each participant (transport: mpi)
  int right_ranks = 1;
  double output_every = 0.0;  // snapshots of the exchanged fields
};

// Writes the job and its participants' configs into `dir`; returns the job
// file.
std::filesystem::path write_job(const std::filesystem::path& dir, const JobOptions& options);

// `cosim run <job> --output <output> [extra...]`.
ProcessResult cosim_run(const std::filesystem::path& job, const std::filesystem::path& output,
                        int timeout_s = 120, const std::vector<std::string>& extra = {});

}  // namespace cosim::testing

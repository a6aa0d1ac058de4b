#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "job/job.hpp"
#include "scratch_directory.hpp"

// An MPI job of two participants on 2 and 3 ranks, whose programs are
// executables in a scratch directory, for the tests of the launch line and
// the Slurm script.
namespace cosim::testing {

class MpmdJob : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* program : {"soil_solver", "water_solver"}) {
      const auto file = scratch_.write(program, "#!/bin/sh\nexit 0\n");
      std::filesystem::permissions(file, std::filesystem::perms::owner_all);
    }
    job_file_ = scratch_.write("job.yaml", job_text());
    job_ = job::load_job(job_file_);
  }

  // `soil_args`: the YAML list of soil's extra arguments.
  std::string job_text(const std::string& soil_args = "[--threads, '1']") const {
    return "kind: job\nname: ranks_demo\nend_time: 1.0\nwindow: 0.1\ntransport: mpi\n"
           "participants:\n"
           "  soil: {executable: ./soil_solver, ranks: 2, args: " +
           soil_args +
           "}\n"
           "  water: {executable: ./water_solver, ranks: 3}\n";
  }

  // A program's path, without `.` components.
  std::filesystem::path program(const std::string& name) const {
    return std::filesystem::absolute(scratch_ / name).lexically_normal();
  }

  ScratchDirectory scratch_;
  std::filesystem::path job_file_;
  job::Job job_;
};

}  // namespace cosim::testing

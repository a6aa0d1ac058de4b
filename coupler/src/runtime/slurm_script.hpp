#pragma once

#include <filesystem>
#include <string>

#include "job/job.hpp"
#include "runtime/mpi_launch.hpp"

// A Slurm batch script of an MPI job (`cosim run job.yaml --output dir
// --slurm-script run.slurm`): one `srun --multi-prog` step starts the
// coupler and every participant's ranks, with the programs and arguments of
// the mpirun line (runtime::mpmd_applications).
namespace cosim::runtime {

struct SlurmScript {
  std::string batch_script;  // #!/bin/bash, #SBATCH lines, srun --multi-prog <conf>
  std::string multi_prog;    // srun's multi-prog configuration
};

// The multi-prog configuration file written next to `script_file`.
std::filesystem::path multi_prog_path(const std::filesystem::path& script_file);

// The two files' contents. The configuration has one line per application:
// its task range (`0` for the coupler, `1-2` for a participant on 2 ranks
// after it, ...) and `env COSIM_APP_INDEX=<i> <program> <arguments>`, i the
// application's index (srun sets no MPI_APPNUM). Arguments are quoted as
// for a shell (shell_join), which srun's parser of the file reads the same
// way. Throws InputError for what that file cannot carry: an argument with
// a line break, or more than 127 words on a line (srun's limit).
SlurmScript slurm_script(const job::Job& job, const std::filesystem::path& job_file,
                         const std::filesystem::path& output_dir, const std::string& job_id,
                         double connect_timeout_s, const std::filesystem::path& script_file,
                         const CheckpointArguments& checkpoints = {});

// Writes the script to `script_file` and its configuration to
// multi_prog_path(script_file), running nothing and creating no output
// directory. An existing script or configuration is refused (InputError)
// unless `overwrite`.
void write_slurm_script(const job::Job& job, const std::filesystem::path& job_file,
                        const std::filesystem::path& output_dir, const std::string& job_id,
                        double connect_timeout_s, const std::filesystem::path& script_file,
                        bool overwrite, const CheckpointArguments& checkpoints = {});

}  // namespace cosim::runtime

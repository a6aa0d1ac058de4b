#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "job/job.hpp"

namespace cosim::runtime {

// The MPMD mpirun command line of an MPI job: the coupler first (world rank
// 0), then one application per participant, each with its coupling options.
std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s);

// The arguments `cosim run` gives a participant: --config, --output and the
// coupling options (among them the coupler's own connect timeout, so that
// the coupler, which judges who failed, gives up first), then the job's
// `args`.
std::vector<std::string> participant_arguments(const job::ParticipantSpec& participant,
                                               const std::filesystem::path& output_dir,
                                               const std::string& endpoint,
                                               const std::string& job_id,
                                               const std::string& config_hash,
                                               double connect_timeout_s);

// Quotes for a POSIX shell where needed.
std::string shell_join(const std::vector<std::string>& words);

}  // namespace cosim::runtime

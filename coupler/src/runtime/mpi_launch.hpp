#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "job/job.hpp"

namespace cosim::runtime {

// One program of an MPI job's MPMD launch: how many ranks run it, and its
// command (the program, then its arguments).
struct MpmdApplication {
  std::string name;  // "coupler" or the participant's name
  int ranks = 1;
  std::vector<std::string> command;
};

// The checkpoint options of `cosim run` an MPI job passes on: the coupler
// takes them as its own, each participant's ranks --cosim-restart with the
// participant's directory of the checkpoint.
struct CheckpointArguments {
  std::string every;  // --checkpoint-every; empty: none
  std::size_t kept = 2;
  std::filesystem::path restart;  // --restart; empty: a fresh start
};

// The applications of an MPI job in launch order: the coupler (`cosim run`,
// world rank 0), then each participant on its `ranks` with the arguments of
// participant_arguments (endpoint mpi://). The mpirun line and the Slurm
// multi-prog file are both made from it, so they start the same programs.
std::vector<MpmdApplication> mpmd_applications(const job::Job& job,
                                               const std::filesystem::path& job_file,
                                               const std::filesystem::path& output_dir,
                                               const std::string& job_id, double connect_timeout_s,
                                               const CheckpointArguments& checkpoints = {});

// The ranks of an MPI job: 1 (the coupler) + the sum of the participants'
// ranks.
int mpi_world_size(const job::Job& job);

// mpirun's binding of `world_size` ranks on a machine of `cores` cores: one
// core each when they fit (--bind-to core), none when they do not or the
// count is unknown (0): oversubscribed ranks pinned to the same cores would
// wait for each other (--bind-to none).
std::vector<std::string> binding_options(int world_size, unsigned cores);

// The most ranks mpirun may start per core of this machine: beyond, a job
// would spend its time switching between processes (and may run out of
// them), which is no way to run it; a cluster runs it (--slurm-script).
inline constexpr int max_ranks_per_core = 16;

// Refuses (InputError at the `ranks` key of the participant with the most
// ranks, exit 2) an MPI job of more ranks than max_ranks_per_core x `cores`
// (nothing refused when the count of cores is unknown, 0).
void check_ranks_fit(const job::Job& job, unsigned cores);

// The cores this process may run on (its CPU affinity, at most
// std::thread::hardware_concurrency()); 0 when unknown.
unsigned available_cores();

// The MPMD mpirun command line of an MPI job: the coupler first (world rank
// 0), then one application per participant, `-np <ranks>` each, with its
// coupling options; bound as binding_options says for `cores` cores.
std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s,
                                     unsigned cores, const CheckpointArguments& checkpoints = {});
// The same for this machine (available_cores()).
std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s,
                                     const CheckpointArguments& checkpoints = {});

// The peer name of part `part` (0-based) of a participant on `parts` ranks:
// `name[part]` when parts > 1, the plain `name` when the participant runs on
// one rank.
std::string part_peer_name(const std::string& participant, int part, int parts);

// One peer name per world rank after the coupler's (rank r is entry r - 1),
// in launch order: each participant's part_peer_name of its ranks.
std::vector<std::string> rank_peer_names(const job::Job& job);

// The arguments `cosim run` gives a participant: --config, --output and the
// coupling options (among them the coupler's own connect timeout, so that
// the coupler, which judges who failed, gives up first; and
// --cosim-solver-processes for a program that starts its solver's processes
// itself), then the job's `args`.
std::vector<std::string> participant_arguments(const job::ParticipantSpec& participant,
                                               const std::filesystem::path& output_dir,
                                               const std::string& endpoint,
                                               const std::string& job_id,
                                               const std::string& config_hash,
                                               double connect_timeout_s);

// Quotes for a POSIX shell where needed.
std::string shell_join(const std::vector<std::string>& words);

}  // namespace cosim::runtime

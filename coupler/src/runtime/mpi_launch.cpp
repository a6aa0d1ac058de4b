#include "runtime/mpi_launch.hpp"

#include <fmt/format.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

#include "cosim/error.hpp"
#include "cosim/runtime/supervisor.hpp"

namespace cosim::runtime {

std::vector<std::string> participant_arguments(const job::ParticipantSpec& participant,
                                               const std::filesystem::path& output_dir,
                                               const std::string& endpoint,
                                               const std::string& job_id,
                                               const std::string& config_hash,
                                               double connect_timeout_s) {
  std::vector<std::string> args;
  if (participant.config) {
    args.push_back("--config");
    args.push_back(participant.config->string());
  }
  args.insert(args.end(),
              {"--output", (output_dir / participant.name).string(), "--cosim-endpoint", endpoint,
               "--cosim-job", job_id, "--cosim-config-hash", config_hash, "--cosim-name",
               participant.name, "--cosim-connect-timeout", fmt::format("{}", connect_timeout_s)});
  if (participant.solver_processes > 0)
    args.insert(args.end(),
                {"--cosim-solver-processes", fmt::format("{}", participant.solver_processes)});
  args.insert(args.end(), participant.args.begin(), participant.args.end());
  return args;
}

std::vector<MpmdApplication> mpmd_applications(const job::Job& job,
                                               const std::filesystem::path& job_file,
                                               const std::filesystem::path& output_dir,
                                               const std::string& job_id, double connect_timeout_s,
                                               const CheckpointArguments& checkpoints) {
  namespace fs = std::filesystem;
  std::vector<MpmdApplication> apps;
  const auto self = self_directory() / "cosim";
  MpmdApplication coupler{"coupler",
                          1,
                          {self.string(), "run", fs::absolute(job_file).string(), "--output",
                           fs::absolute(output_dir).string(), "--job-id", job_id,
                           "--connect-timeout", fmt::format("{}", connect_timeout_s)}};
  if (!checkpoints.every.empty())
    coupler.command.insert(coupler.command.end(),
                           {"--checkpoint-every", checkpoints.every, "--checkpoints-kept",
                            fmt::format("{}", checkpoints.kept)});
  if (!checkpoints.restart.empty())
    coupler.command.insert(coupler.command.end(),
                           {"--restart", fs::absolute(checkpoints.restart).string()});
  apps.push_back(std::move(coupler));
  const auto base = job_file.parent_path();
  for (const auto& p : job.participants) {
    MpmdApplication app{p.name, p.ranks, {resolve_executable(p.executable, base).string()}};
    const auto args = participant_arguments(p, fs::absolute(output_dir), "mpi://", job_id,
                                            job.config_hash, connect_timeout_s);
    app.command.insert(app.command.end(), args.begin(), args.end());
    if (!checkpoints.restart.empty())
      app.command.insert(
          app.command.end(),
          {"--cosim-restart", (fs::absolute(checkpoints.restart) / p.name).string()});
    apps.push_back(std::move(app));
  }
  return apps;
}

int mpi_world_size(const job::Job& job) {
  int size = 1;
  for (const auto& p : job.participants) size += p.ranks;
  return size;
}

std::vector<std::string> binding_options(int world_size, unsigned cores) {
  const bool fits = cores > 0 && world_size > 0 && static_cast<unsigned>(world_size) <= cores;
  return {"--bind-to", fits ? "core" : "none"};
}

void check_ranks_fit(const job::Job& job, unsigned cores) {
  const int world = mpi_world_size(job);
  const long most = static_cast<long>(max_ranks_per_core) * static_cast<long>(cores);
  if (cores == 0 || world <= most) return;
  const auto widest =
      std::max_element(job.participants.begin(), job.participants.end(),
                       [](const auto& a, const auto& b) { return a.ranks < b.ranks; });
  const std::string what = fmt::format(
      "the job needs {} ranks (the coupler and its participants'), more than mpirun can run "
      "here: {} core{} x {} ranks per core at most; give fewer ranks, or write a batch script "
      "for a cluster with --slurm-script",
      world, cores, cores == 1 ? "" : "s", max_ranks_per_core);
  if (widest->ranks_where.line == 0) throw InputError(what);
  throw InputError(widest->ranks_where, fmt::format("participants.{}.ranks", widest->name), what);
}

unsigned available_cores() {
  const unsigned hardware = std::thread::hardware_concurrency();
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof(set), &set) != 0) return hardware;
  const auto allowed = static_cast<unsigned>(CPU_COUNT(&set));
  return hardware == 0 ? allowed : std::min(allowed, hardware);
}

std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s,
                                     unsigned cores, const CheckpointArguments& checkpoints) {
  std::vector<std::string> cmd{"mpirun", "--oversubscribe"};
  if (::geteuid() == 0) cmd.push_back("--allow-run-as-root");
  // A participant's solver processes of its own share the machine's cores.
  int processes = mpi_world_size(job);
  for (const auto& p : job.participants) processes += p.solver_processes;
  const auto binding = binding_options(processes, cores);
  cmd.insert(cmd.end(), binding.begin(), binding.end());
  // Waiting ranks yield their core: participants sub-cycle while others wait.
  cmd.insert(cmd.end(), {"--mca", "mpi_yield_when_idle", "1"});
  bool first = true;
  for (const auto& app :
       mpmd_applications(job, job_file, output_dir, job_id, connect_timeout_s, checkpoints)) {
    if (!first) cmd.push_back(":");
    first = false;
    cmd.insert(cmd.end(), {"-np", fmt::format("{}", app.ranks)});
    cmd.insert(cmd.end(), app.command.begin(), app.command.end());
  }
  return cmd;
}

std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s,
                                     const CheckpointArguments& checkpoints) {
  return mpi_command(job, job_file, output_dir, job_id, connect_timeout_s, available_cores(),
                     checkpoints);
}

std::string part_peer_name(const std::string& participant, int part, int parts) {
  return parts > 1 ? fmt::format("{}[{}]", participant, part) : participant;
}

std::vector<std::string> rank_peer_names(const job::Job& job) {
  std::vector<std::string> names;
  for (const auto& p : job.participants)
    for (int part = 0; part < p.ranks; ++part)
      names.push_back(part_peer_name(p.name, part, p.ranks));
  return names;
}

std::string shell_join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    const bool plain = !w.empty() && w.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMN"
                                         "OPQRSTUVWXYZ0123456789_-./:=+@,") == std::string::npos;
    if (plain) {
      out += w;
      continue;
    }
    out += '\'';
    for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

}  // namespace cosim::runtime

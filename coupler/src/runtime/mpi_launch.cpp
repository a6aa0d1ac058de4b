#include "runtime/mpi_launch.hpp"

#include <fmt/format.h>
#include <unistd.h>

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
  args.insert(args.end(), participant.args.begin(), participant.args.end());
  return args;
}

std::vector<std::string> mpi_command(const job::Job& job, const std::filesystem::path& job_file,
                                     const std::filesystem::path& output_dir,
                                     const std::string& job_id, double connect_timeout_s) {
  std::vector<std::string> cmd{"mpirun", "--oversubscribe"};
  if (::geteuid() == 0) cmd.push_back("--allow-run-as-root");
  // Waiting ranks yield their core: participants sub-cycle while others wait.
  cmd.insert(cmd.end(), {"--mca", "mpi_yield_when_idle", "1"});
  const auto self = self_directory() / "cosim";
  cmd.insert(cmd.end(),
             {"-np", "1", self.string(), "run", std::filesystem::absolute(job_file).string(),
              "--output", std::filesystem::absolute(output_dir).string(), "--job-id", job_id,
              "--connect-timeout", fmt::format("{}", connect_timeout_s)});
  const auto base = job_file.parent_path();
  for (const auto& p : job.participants) {
    cmd.insert(cmd.end(), {":", "-np", "1", resolve_executable(p.executable, base).string()});
    auto args = participant_arguments(p, std::filesystem::absolute(output_dir), "mpi://", job_id,
                                      job.config_hash, connect_timeout_s);
    cmd.insert(cmd.end(), args.begin(), args.end());
  }
  return cmd;
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

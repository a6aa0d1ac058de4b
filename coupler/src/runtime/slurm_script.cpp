#include "runtime/slurm_script.hpp"

#include <fmt/format.h>

#include <vector>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "runtime/mpi_launch.hpp"

namespace cosim::runtime {

namespace {

namespace fs = std::filesystem;

// srun reads at most 127 words of a multi-prog line (program included) and
// drops the rest without an error.
constexpr std::size_t max_multi_prog_words = 127;

// The multi-prog file and the batch script are read line by line.
void check_one_line(const std::string& word, const std::string& what) {
  if (word.find_first_of("\n\r") != std::string::npos)
    throw InputError(fmt::format(
        "--slurm-script: {} '{}' holds a line break, which a Slurm multi-prog file cannot carry",
        what, word));
}

std::string task_range(int first, int ranks) {
  return ranks == 1 ? fmt::format("{}", first) : fmt::format("{}-{}", first, first + ranks - 1);
}

}  // namespace

fs::path multi_prog_path(const fs::path& script_file) {
  return fs::path(script_file.string() + ".multi-prog.conf");
}

SlurmScript slurm_script(const job::Job& job, const fs::path& job_file, const fs::path& output_dir,
                         const std::string& job_id, double connect_timeout_s,
                         const fs::path& script_file, const CheckpointArguments& checkpoints) {
  const fs::path script = fs::absolute(script_file);
  const fs::path conf = multi_prog_path(script);
  const fs::path output = fs::absolute(output_dir);
  check_one_line(script.string(), "the script's path");
  const auto apps =
      mpmd_applications(job, job_file, output_dir, job_id, connect_timeout_s, checkpoints);

  SlurmScript s;
  s.multi_prog = fmt::format(
      "# srun --multi-prog configuration of job '{}' (id {}), written by `cosim run "
      "--slurm-script`\n"
      "# task range, then the program: COSIM_APP_INDEX is the application's index (srun sets no "
      "MPI_APPNUM)\n",
      job.name, job_id);
  std::string layout;
  int first = 0;
  for (std::size_t i = 0; i < apps.size(); ++i) {
    const MpmdApplication& app = apps[i];
    std::vector<std::string> words{"env", fmt::format("COSIM_APP_INDEX={}", i)};
    words.insert(words.end(), app.command.begin(), app.command.end());
    for (const auto& w : words) check_one_line(w, "argument");
    if (words.size() > max_multi_prog_words)
      throw InputError(fmt::format(
          "--slurm-script: the command of {} has {} words; a Slurm multi-prog line holds at "
          "most {} (shorten participants.{}.args)",
          i == 0 ? std::string("the coupler") : "participant '" + app.name + "'", words.size(),
          max_multi_prog_words, app.name));
    s.multi_prog += task_range(first, app.ranks) + " " + shell_join(words) + "\n";
    if (i > 0) {
      layout +=
          fmt::format("{}#   participant '{}': {} rank{} (tasks {})", layout.empty() ? "" : "\n",
                      app.name, app.ranks, app.ranks == 1 ? "" : "s", task_range(first, app.ranks));
      if (const int own = job.participants[i - 1].solver_processes; own > 0)
        layout += fmt::format(
            ", which starts its solver on {} processes of its own with mpirun on its node: "
            "leave that node {} more cores",
            own, own);
    }
    first += app.ranks;
  }

  s.batch_script = fmt::format(
      R"script(#!/bin/bash
#SBATCH --job-name={name}
#SBATCH --ntasks={tasks}
#
# The coupled job '{name}' (id {id}, {job_file}) as one MPMD step
# of {tasks} tasks: the coupler (task 0) and
{layout}
# The programs and their arguments are in {conf}.
# Written by `cosim run --slurm-script`; submit it with
#   sbatch {script}
# Add your site's #SBATCH lines (--time, --partition, --account, ...) above, and
# srun's MPI plugin if your site needs one (srun --mpi=pmix).
set -euo pipefail

# Two runs never mix in one directory: a non-empty one is refused.
output={output}
if [ -d "$output" ] && [ -n "$(ls -A "$output")" ]; then
  echo "cosim: output directory $output is not empty; choose another --output" >&2
  exit 2
fi
mkdir -p "$output"

# One failing task ends the job.
srun --kill-on-bad-exit=1 --multi-prog {conf_word}
)script",
      fmt::arg("name", job.name), fmt::arg("tasks", mpi_world_size(job)), fmt::arg("id", job_id),
      fmt::arg("job_file", fs::absolute(job_file).string()), fmt::arg("layout", layout),
      fmt::arg("conf", conf.string()), fmt::arg("script", shell_join({script.string()})),
      fmt::arg("output", shell_join({output.string()})),
      fmt::arg("conf_word", shell_join({conf.string()})));
  return s;
}

void write_slurm_script(const job::Job& job, const fs::path& job_file, const fs::path& output_dir,
                        const std::string& job_id, double connect_timeout_s,
                        const fs::path& script_file, bool overwrite,
                        const CheckpointArguments& checkpoints) {
  const SlurmScript s =
      slurm_script(job, job_file, output_dir, job_id, connect_timeout_s, script_file, checkpoints);
  const fs::path conf = multi_prog_path(script_file);
  for (const fs::path& file : {script_file, conf}) {
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (!fs::exists(status)) continue;
    if (!fs::is_regular_file(status))
      throw InputError(fmt::format("--slurm-script: '{}' exists and is not a file", file.string()));
    if (!overwrite)
      throw InputError(fmt::format(
          "--slurm-script: '{}' exists; pass --overwrite to replace it, or choose another file",
          file.string()));
  }
  // The configuration first: a script never names a file not yet written.
  write_file_atomically(conf, s.multi_prog);
  write_file_atomically(script_file, s.batch_script);
  std::error_code ignored;
  fs::permissions(script_file, fs::perms::owner_exec, fs::perm_options::add, ignored);
}

}  // namespace cosim::runtime

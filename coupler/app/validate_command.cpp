#include "validate_command.hpp"

#include <fmt/format.h>
#include <stdlib.h>

#include <iostream>

#include "bench/backend_catalog.hpp"
#include "cosim/error.hpp"
#include "cosim/io/tail_lines.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "cosim/runtime/supervisor.hpp"
#include "job/job.hpp"

namespace cosim::app {

namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

// A solver checks its config in well under this; one that takes longer is
// stuck (or given an absurd file) and is stopped.
constexpr milliseconds validate_timeout{60000};

// A scratch directory for the solvers' console output, removed on return.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = (fs::path(tmp && *tmp ? tmp : "/tmp") / "cosim-validate-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw Error(ExitCode::internal_error, "cannot create a scratch directory for validation");
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string indented(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines)
    if (!l.empty()) out += "    " + l + "\n";
  return out;
}

}  // namespace

int validate_job(const std::string& job_file) {
  const job::Job job = job::load_job(job_file, bench::programs_starting_their_processes());
  std::cout << fmt::format(
      "{}: job '{}': {} participants, {} exchanges, {} windows of {} s, config hash {}\n", job_file,
      job.name, job.participants.size(), job.exchanges.size(), job.windows(), job.window,
      job.config_hash);

  const ScratchDirectory scratch;
  runtime::Supervisor supervisor;
  for (const auto& p : job.participants) {
    if (!p.config) continue;
    runtime::ChildSpec child;
    child.name = p.name;
    child.executable = runtime::resolve_executable(p.executable, job.file.parent_path());
    child.args = {"--validate", "--config", p.config->string()};
    child.log_file = scratch.path() / (p.name + ".log");
    supervisor.start(child);
  }
  const auto exits = supervisor.wait_all(validate_timeout, &runtime::stop_flag());
  if (runtime::stop_requested() || supervisor.running() > 0) {
    supervisor.stop_all(milliseconds(1000));
    throw Error(ExitCode::participant_failed,
                runtime::stop_requested()
                    ? runtime::describe_stop()
                    : fmt::format("a solver did not finish validating its config within {} s",
                                  validate_timeout.count() / 1000));
  }
  ExitCode worst = ExitCode::success;
  for (const auto& p : job.participants) {
    if (!p.config) {
      std::cout << fmt::format("  {}: no config file\n", p.name);
      continue;
    }
    const auto e =
        std::find_if(exits.begin(), exits.end(), [&](auto& x) { return x.name == p.name; });
    const auto lines = tail_lines(supervisor.log_file(p.name), 20);
    if (e != exits.end() && e->success()) {
      std::cout << fmt::format("  {} ({}): {}\n", p.name, p.executable,
                               lines.empty() ? "valid" : lines.back());
      continue;
    }
    const ExitCode code = e == exits.end() ? ExitCode::participant_failed : e->coupled_exit_code();
    if (worst == ExitCode::success || code == ExitCode::bad_input) worst = code;
    std::cerr << fmt::format("  {} ({}): config {} is not valid ({}):\n{}", p.name, p.executable,
                             p.config->string(), e == exits.end() ? "no answer" : e->describe(),
                             indented(lines));
  }
  if (worst == ExitCode::success)
    std::cout << fmt::format("{}: job '{}' is valid\n", job_file, job.name);
  else
    std::cerr << fmt::format("{}: job '{}' is not valid: see the participants above\n", job_file,
                             job.name);
  return to_int(worst);
}

}  // namespace cosim::app

#pragma once

#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cosim/exit_codes.hpp"

// Starts participant processes and makes sure none outlives the coupler:
// each child leads its own process group (so its own children are stopped
// with it) and is killed by the kernel if the coupler dies (PR_SET_PDEATHSIG).
namespace cosim::runtime {

struct ChildSpec {
  std::string name;
  std::filesystem::path executable;
  std::vector<std::string> args;   // without argv[0]
  std::filesystem::path log_file;  // receives the child's stdout and stderr
  // Set in the child's environment, on top of this process's (secrets go
  // here, never into args: any local user can read a command line).
  std::vector<std::pair<std::string, std::string>> environment = {};
  // Prefixes of this process's variables the child does not inherit (an
  // MPI rank's launch variables, which would make the child's own mpirun
  // or MPI_Init join the parent's job).
  std::vector<std::string> environment_left_out = {};
};

struct ChildExit {
  std::string name;
  pid_t pid = 0;
  int exit_status = 0;  // when exited normally
  int signal = 0;       // when killed by a signal
  bool success() const { return signal == 0 && exit_status == 0; }
  std::string describe() const;  // "exited with status 4" / "was killed by SIGKILL"
  // What the coupler makes of it: a participant's bad input (2) and
  // numerical failure (4) pass through; anything else is participant_failed.
  ExitCode coupled_exit_code() const;
};

class Supervisor {
 public:
  Supervisor() = default;
  ~Supervisor();  // stops every child still running
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  // Starts the child; a program that cannot be executed (missing, not
  // executable, a command line beyond the kernel's limits) is an Error
  // naming it, raised here rather than reported later as the child's exit.
  pid_t start(const ChildSpec& spec);
  // Reaps children that have exited, without blocking.
  std::vector<ChildExit> reap();
  // Waits up to `timeout` for all children to exit by themselves; stops
  // waiting early, returning what exited so far, when `stop` becomes true.
  std::vector<ChildExit> wait_all(std::chrono::milliseconds timeout,
                                  const std::atomic<bool>* stop = nullptr);
  // Waits up to `timeout` for the child `name` alone; its exit, or nothing
  // when it is still running (or was not started). Others that exit
  // meanwhile are reaped and kept for exited().
  std::optional<ChildExit> wait_for(const std::string& name, std::chrono::milliseconds timeout);
  // SIGTERM to every child's process group, then SIGKILL after `grace`;
  // reaps them all.
  std::vector<ChildExit> stop_all(std::chrono::milliseconds grace);

  std::size_t running() const { return children_.size(); }
  // The names of the children still running, quoted: "'left', 'right'".
  std::string running_names() const;
  // Whether every child still running is stopped (SIGSTOP, a debugger): none
  // of them can do anything before it is continued.
  bool all_running_stopped() const;
  // Every child reaped so far, in the order they were reaped.
  const std::vector<ChildExit>& exited() const { return exited_; }
  std::optional<pid_t> pid_of(const std::string& name) const;
  const std::filesystem::path& log_file(const std::string& name) const;

 private:
  struct Child {
    std::string name;
    std::filesystem::path log_file;
  };
  std::map<pid_t, Child> children_;
  std::map<std::string, std::filesystem::path> logs_;
  std::vector<ChildExit> exited_;
};

// Finds a participant's program: a path containing '/' as given (relative to
// `base_dir`), otherwise next to the running `cosim` executable, then on PATH.
// Throws InputError naming the executable when none is found.
std::filesystem::path resolve_executable(const std::string& name_or_path,
                                         const std::filesystem::path& base_dir);

// The directory of the running executable (/proc/self/exe).
std::filesystem::path self_directory();

}  // namespace cosim::runtime

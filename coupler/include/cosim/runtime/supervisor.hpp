#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

// Starts participant processes and makes sure none outlives the coupler:
// each child leads its own process group (so its own children are stopped
// with it) and is killed by the kernel if the coupler dies (PR_SET_PDEATHSIG).
namespace cosim::runtime {

struct ChildSpec {
  std::string name;
  std::filesystem::path executable;
  std::vector<std::string> args;   // without argv[0]
  std::filesystem::path log_file;  // receives the child's stdout and stderr
};

struct ChildExit {
  std::string name;
  pid_t pid = 0;
  int exit_status = 0;  // when exited normally
  int signal = 0;       // when killed by a signal
  bool success() const { return signal == 0 && exit_status == 0; }
  std::string describe() const;  // "exited with status 4" / "was killed by SIGKILL"
};

class Supervisor {
 public:
  Supervisor() = default;
  ~Supervisor();  // stops every child still running
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  pid_t start(const ChildSpec& spec);
  // Reaps children that have exited, without blocking.
  std::vector<ChildExit> reap();
  // Waits up to `timeout` for all children to exit by themselves.
  std::vector<ChildExit> wait_all(std::chrono::milliseconds timeout);
  // SIGTERM to every child's process group, then SIGKILL after `grace`;
  // reaps them all.
  std::vector<ChildExit> stop_all(std::chrono::milliseconds grace);

  std::size_t running() const { return children_.size(); }
  std::optional<pid_t> pid_of(const std::string& name) const;
  const std::filesystem::path& log_file(const std::string& name) const;

 private:
  struct Child {
    std::string name;
    std::filesystem::path log_file;
  };
  std::map<pid_t, Child> children_;
  std::map<std::string, std::filesystem::path> logs_;
};

// Finds a participant's program: a path containing '/' as given (relative to
// `base_dir`), otherwise next to the running `cosim` executable, then on PATH.
// Throws InputError naming the executable when none is found.
std::filesystem::path resolve_executable(const std::string& name_or_path,
                                         const std::filesystem::path& base_dir);

// The directory of the running executable (/proc/self/exe).
std::filesystem::path self_directory();

}  // namespace cosim::runtime

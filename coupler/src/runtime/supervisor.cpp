#include "cosim/runtime/supervisor.hpp"

#include <fcntl.h>
#include <linux/close_range.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <fmt/format.h>

#include "cosim/error.hpp"

namespace cosim::runtime {

namespace {

ChildExit decode_status(pid_t pid, const std::string& name, int status) {
  ChildExit e;
  e.name = name;
  e.pid = pid;
  if (WIFEXITED(status)) e.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) e.signal = WTERMSIG(status);
  return e;
}

}  // namespace

std::string ChildExit::describe() const {
  if (signal != 0) return fmt::format("was killed by signal {} ({})", signal, ::strsignal(signal));
  return fmt::format("exited with status {}", exit_status);
}

Supervisor::~Supervisor() {
  if (!children_.empty()) stop_all(std::chrono::milliseconds(2000));
}

pid_t Supervisor::start(const ChildSpec& spec) {
  // Everything the child needs is prepared before fork: between fork and
  // exec only async-signal-safe calls are allowed.
  std::vector<std::string> args_storage;
  args_storage.push_back(spec.executable.string());
  args_storage.insert(args_storage.end(), spec.args.begin(), spec.args.end());
  std::vector<char*> argv;
  for (auto& a : args_storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string exe = spec.executable.string();
  const int log_fd = ::open(spec.log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0)
    throw Error(ExitCode::bad_input, fmt::format("cannot open log file {} for participant '{}': {}",
                                                 spec.log_file.string(), spec.name,
                                                 std::strerror(errno)));
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(log_fd);
    throw Error(ExitCode::participant_failed,
                fmt::format("cannot start participant '{}': fork failed: {}", spec.name,
                            std::strerror(errno)));
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the coupler died before prctl
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    if (null_fd >= 0) ::dup2(null_fd, STDIN_FILENO);
    ::syscall(SYS_close_range, 3U, ~0U, 0U);
    ::execv(exe.c_str(), argv.data());
    static const char message[] = "cosim: exec failed for the participant executable\n";
    [[maybe_unused]] auto ignored = ::write(STDERR_FILENO, message, sizeof(message) - 1);
    ::_exit(127);
  }
  ::close(log_fd);
  ::setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  children_[pid] = {spec.name, spec.log_file};
  logs_[spec.name] = spec.log_file;
  return pid;
}

std::vector<ChildExit> Supervisor::reap() {
  std::vector<ChildExit> exits;
  for (auto it = children_.begin(); it != children_.end();) {
    int status = 0;
    const pid_t r = ::waitpid(it->first, &status, WNOHANG);
    if (r == it->first) {
      exits.push_back(decode_status(it->first, it->second.name, status));
      // The child's own children (its process group) go with it.
      ::kill(-it->first, SIGKILL);
      it = children_.erase(it);
    } else {
      ++it;
    }
  }
  return exits;
}

std::vector<ChildExit> Supervisor::wait_all(std::chrono::milliseconds timeout) {
  std::vector<ChildExit> exits;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto batch = reap();
    exits.insert(exits.end(), batch.begin(), batch.end());
    if (children_.empty() || std::chrono::steady_clock::now() >= deadline) return exits;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::vector<ChildExit> Supervisor::stop_all(std::chrono::milliseconds grace) {
  for (const auto& [pid, child] : children_) ::kill(-pid, SIGTERM);
  auto exits = wait_all(grace);
  for (const auto& [pid, child] : children_) ::kill(-pid, SIGKILL);
  auto killed = wait_all(std::chrono::milliseconds(10000));
  exits.insert(exits.end(), killed.begin(), killed.end());
  return exits;
}

std::optional<pid_t> Supervisor::pid_of(const std::string& name) const {
  for (const auto& [pid, child] : children_)
    if (child.name == name) return pid;
  return std::nullopt;
}

const std::filesystem::path& Supervisor::log_file(const std::string& name) const {
  static const std::filesystem::path none;
  auto it = logs_.find(name);
  return it == logs_.end() ? none : it->second;
}

std::filesystem::path self_directory() {
  std::error_code ec;
  auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::current_path() : exe.parent_path();
}

std::filesystem::path resolve_executable(const std::string& name_or_path,
                                         const std::filesystem::path& base_dir) {
  namespace fs = std::filesystem;
  auto executable = [](const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
  };
  if (name_or_path.find('/') != std::string::npos) {
    fs::path p = name_or_path;
    if (p.is_relative()) p = base_dir / p;
    if (executable(p)) return fs::absolute(p);
    throw InputError(fmt::format("participant executable '{}' not found or not executable ({})",
                                 name_or_path, p.string()));
  }
  if (auto p = self_directory() / name_or_path; executable(p)) return p;
  if (const char* path = std::getenv("PATH")) {
    std::string_view rest = path;
    while (!rest.empty()) {
      const auto colon = rest.find(':');
      const fs::path dir(std::string(rest.substr(0, colon)));
      if (!dir.empty() && executable(dir / name_or_path)) return dir / name_or_path;
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  throw InputError(fmt::format("participant executable '{}' found neither next to cosim ({}) nor "
                               "on PATH",
                               name_or_path, self_directory().string()));
}

}  // namespace cosim::runtime

#include "cosim/runtime/supervisor.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/close_range.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <thread>

#include "cosim/error.hpp"

extern char** environ;

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

// The kernel's limits on a command line (MAX_ARG_STRLEN per argument; the
// whole, with the environment, well below the usual 2 MiB ARG_MAX).
constexpr std::size_t max_argument_bytes = 128 * 1024;
constexpr std::size_t max_command_line_bytes = 1024 * 1024;

}  // namespace

std::string ChildExit::describe() const {
  if (signal != 0) return fmt::format("was killed by signal {} ({})", signal, ::strsignal(signal));
  return fmt::format("exited with status {}", exit_status);
}

ExitCode ChildExit::coupled_exit_code() const {
  if (signal == 0 && exit_status == to_int(ExitCode::bad_input)) return ExitCode::bad_input;
  if (signal == 0 && exit_status == to_int(ExitCode::numerical_failure))
    return ExitCode::numerical_failure;
  return ExitCode::participant_failed;
}

Supervisor::~Supervisor() {
  if (!children_.empty()) stop_all(std::chrono::milliseconds(2000));
}

pid_t Supervisor::start(const ChildSpec& spec) {
  std::size_t command_line = spec.executable.string().size() + 1;
  for (const auto& a : spec.args) {
    if (a.size() >= max_argument_bytes)
      throw Error(ExitCode::bad_input,
                  fmt::format("cannot start participant '{}': an argument of its command line is "
                              "{} bytes long (the limit is {})",
                              spec.name, a.size(), max_argument_bytes));
    command_line += a.size() + 1;
  }
  if (command_line > max_command_line_bytes)
    throw Error(ExitCode::bad_input,
                fmt::format("cannot start participant '{}': its command line is {} bytes long "
                            "(the limit is {})",
                            spec.name, command_line, max_command_line_bytes));
  // Everything the child needs is prepared before fork: between fork and
  // exec only async-signal-safe calls are allowed.
  std::vector<std::string> args_storage;
  args_storage.push_back(spec.executable.string());
  args_storage.insert(args_storage.end(), spec.args.begin(), spec.args.end());
  std::vector<char*> argv;
  for (auto& a : args_storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> environment_storage;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view entry(*e);
    const std::string_view key = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(spec.environment.begin(), spec.environment.end(),
                                      [&](auto& kv) { return key == kv.first; });
    const bool left_out =
        std::any_of(spec.environment_left_out.begin(), spec.environment_left_out.end(),
                    [&](const std::string& prefix) { return key.starts_with(prefix); });
    if (!replaced && !left_out) environment_storage.emplace_back(entry);
  }
  for (const auto& [key, value] : spec.environment)
    environment_storage.push_back(key + "=" + value);
  std::vector<char*> envp;
  for (auto& e : environment_storage) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string exe = spec.executable.string();
  const int log_fd = ::open(spec.log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0)
    throw Error(ExitCode::bad_input,
                fmt::format("cannot open log file {} for participant '{}': {}",
                            spec.log_file.string(), spec.name, std::strerror(errno)));
  // The child reports a failed exec through this pipe; a successful exec
  // closes it (O_CLOEXEC) and the parent reads nothing.
  int exec_report[2];
  if (::pipe2(exec_report, O_CLOEXEC) != 0) {
    ::close(log_fd);
    throw Error(ExitCode::participant_failed,
                fmt::format("cannot start participant '{}': pipe failed: {}", spec.name,
                            std::strerror(errno)));
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(log_fd);
    ::close(exec_report[0]);
    ::close(exec_report[1]);
    throw Error(ExitCode::participant_failed,
                fmt::format("cannot start participant '{}': fork failed: {}", spec.name,
                            std::strerror(errno)));
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the coupler died before prctl
    // exec resets caught signals, not ignored ones: the coupler's ignored
    // SIGPIPE is not the child's.
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    ::sigaction(SIGPIPE, &default_action, nullptr);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    if (null_fd >= 0) ::dup2(null_fd, STDIN_FILENO);
    if (exec_report[1] != 3) ::dup3(exec_report[1], 3, O_CLOEXEC);
    ::syscall(SYS_close_range, 4U, ~0U, 0U);
    ::execve(exe.c_str(), argv.data(), envp.data());
    const int error = errno;
    [[maybe_unused]] auto ignored = ::write(3, &error, sizeof(error));
    ::_exit(127);
  }
  ::close(log_fd);
  ::close(exec_report[1]);
  ::setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  int exec_error = 0;
  ssize_t got = 0;
  do {
    got = ::read(exec_report[0], &exec_error, sizeof(exec_error));
  } while (got < 0 && errno == EINTR);
  ::close(exec_report[0]);
  if (got == static_cast<ssize_t>(sizeof(exec_error))) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    const bool input = exec_error == E2BIG || exec_error == ENOENT || exec_error == EACCES ||
                       exec_error == ENOEXEC || exec_error == ENAMETOOLONG;
    throw Error(input ? ExitCode::bad_input : ExitCode::participant_failed,
                fmt::format("cannot start participant '{}' ({}): {}", spec.name, exe,
                            std::strerror(exec_error)));
  }
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
      exited_.push_back(exits.back());
      // The child's own children (its process group) go with it.
      ::kill(-it->first, SIGKILL);
      it = children_.erase(it);
    } else {
      ++it;
    }
  }
  return exits;
}

std::vector<ChildExit> Supervisor::wait_all(std::chrono::milliseconds timeout,
                                            const std::atomic<bool>* stop) {
  std::vector<ChildExit> exits;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto batch = reap();
    exits.insert(exits.end(), batch.begin(), batch.end());
    if (children_.empty() || std::chrono::steady_clock::now() >= deadline) return exits;
    if (stop && stop->load()) return exits;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::optional<ChildExit> Supervisor::wait_for(const std::string& name,
                                              std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    reap();
    for (auto it = exited_.rbegin(); it != exited_.rend(); ++it)
      if (it->name == name) return *it;
    if (!pid_of(name) || std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

std::vector<ChildExit> Supervisor::stop_all(std::chrono::milliseconds grace) {
  for (const auto& [pid, child] : children_) {
    ::kill(-pid, SIGTERM);
    ::kill(-pid, SIGCONT);  // a stopped child handles its SIGTERM too
  }
  auto exits = wait_all(grace);
  for (const auto& [pid, child] : children_) ::kill(-pid, SIGKILL);
  auto killed = wait_all(std::chrono::milliseconds(10000));
  exits.insert(exits.end(), killed.begin(), killed.end());
  return exits;
}

std::string Supervisor::running_names() const {
  std::string names;
  for (const auto& [pid, child] : children_)
    names += (names.empty() ? "'" : ", '") + child.name + "'";
  return names;
}

bool Supervisor::all_running_stopped() const {
  for (const auto& [pid, child] : children_) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string stat;
    std::getline(in, stat);
    const auto end = stat.rfind(')');
    if (end == std::string::npos || end + 2 >= stat.size() || stat[end + 2] != 'T') return false;
  }
  return true;
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
  throw InputError(
      fmt::format("participant executable '{}' found neither next to cosim ({}) nor "
                  "on PATH",
                  name_or_path, self_directory().string()));
}

}  // namespace cosim::runtime

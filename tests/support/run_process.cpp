#include "run_process.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <thread>

#include "text_files.hpp"

namespace cosim::testing {

std::filesystem::path binary(const std::string& name) {
  return std::filesystem::path(COSIM_BINARY_DIR) / "bin" / name;
}

std::filesystem::path fresh_directory(const std::string& name) {
  auto dir = std::filesystem::path(COSIM_BINARY_DIR) / "test_runs" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

pid_t spawn(const std::vector<std::string>& args, const std::filesystem::path& log) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    // A test killed by CTest's timeout (or by hand) takes the program it runs
    // with it: SIGTERM lets `cosim run` and `cosim bench` stop their own children.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fd);
  if (pid < 0) throw std::runtime_error("fork failed");
  return pid;
}

ProcessResult wait_for(pid_t pid, const std::filesystem::path& log, std::chrono::seconds timeout) {
  ProcessResult r;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!r.timed_out && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.output = read_text(log);
  return r;
}

ProcessResult run(const std::vector<std::string>& args, std::chrono::seconds timeout) {
  static int counter = 0;
  const auto log =
      std::filesystem::path(COSIM_BINARY_DIR) / "test_runs" /
      ("process_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".log");
  std::filesystem::create_directories(log.parent_path());
  return wait_for(spawn(args, log), log, timeout);
}

bool process_exists(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

pid_t wait_for_pid_file(const std::filesystem::path& file, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in(file);
    pid_t pid = 0;
    if (in >> pid && pid > 0) return pid;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  throw std::runtime_error("no pid file " + file.string());
}

}  // namespace cosim::testing

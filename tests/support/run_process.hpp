#pragma once

#include <signal.h>
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

// Helpers for tests that start `cosim` and participants as real processes.
namespace cosim::testing {

struct ProcessResult {
  int exit_code = -1;  // -1 when killed by a signal or timed out
  bool timed_out = false;
  std::string output;  // stdout and stderr
};

std::filesystem::path binary(const std::string& name);  // build/bin/<name>
std::filesystem::path fresh_directory(const std::string& name);

// Starts `args[0]` with stdout+stderr to `log`; returns its pid.
pid_t spawn(const std::vector<std::string>& args, const std::filesystem::path& log);
// Waits for `pid` up to `timeout` (then kills it); returns the result with
// the log's contents.
ProcessResult wait_for(pid_t pid, const std::filesystem::path& log, std::chrono::seconds timeout);
ProcessResult run(const std::vector<std::string>& args, std::chrono::seconds timeout);

bool process_exists(pid_t pid);
// Reads an integer pid from a file, waiting up to `timeout` for it to appear.
pid_t wait_for_pid_file(const std::filesystem::path& file, std::chrono::seconds timeout);

}  // namespace cosim::testing

#pragma once

#include <string_view>

// Process exit codes shared by `cosim` and every solver (architecture.md §6).
namespace cosim {

enum class ExitCode : int {
  success = 0,
  internal_error = 1,         // a bug in cosim itself: please report it
  bad_input = 2,              // config, mesh, arguments: the message names file, key and line
  participant_failed = 3,     // a coupled participant died or broke the protocol
  numerical_failure = 4,      // NaN, or a CFL violation adaptive stepping could not recover
  stopped_at_checkpoint = 5,  // asked to stop (SIGTERM), it wrote a checkpoint and stopped
};

constexpr int to_int(ExitCode code) {
  return static_cast<int>(code);
}

// "bad_input", "numerical_failure", ...: how summary.json and the abort
// message of the coupling protocol name an exit code.
constexpr const char* to_string(ExitCode code) {
  switch (code) {
    case ExitCode::success:
      return "success";
    case ExitCode::internal_error:
      return "internal_error";
    case ExitCode::bad_input:
      return "bad_input";
    case ExitCode::participant_failed:
      return "participant_failed";
    case ExitCode::numerical_failure:
      return "numerical_failure";
    case ExitCode::stopped_at_checkpoint:
      return "stopped_at_checkpoint";
  }
  return "unknown";
}

// The code named by to_string, or internal_error for any other text.
constexpr ExitCode exit_code_from_string(std::string_view name) {
  for (ExitCode code : {ExitCode::success, ExitCode::bad_input, ExitCode::participant_failed,
                        ExitCode::numerical_failure, ExitCode::stopped_at_checkpoint})
    if (name == to_string(code)) return code;
  return ExitCode::internal_error;
}

}  // namespace cosim

#pragma once

// Process exit codes shared by `cosim` and every solver (DESIGN.md §6).
namespace cosim {

enum class ExitCode : int {
  success = 0,
  internal_error = 1,      // a bug in cosim itself: please report it
  bad_input = 2,           // config, mesh, arguments: the message names file, key and line
  participant_failed = 3,  // a coupled participant died or broke the protocol
  numerical_failure = 4,   // NaN, or a CFL violation adaptive stepping could not recover
};

constexpr int to_int(ExitCode code) { return static_cast<int>(code); }

}  // namespace cosim

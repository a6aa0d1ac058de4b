#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "run_process.hpp"

// A coupled run continued from a checkpoint against the uninterrupted run
// (architecture.md §14), for the tests of `cosim run --restart`: the rows
// each CSV has after the checkpoint and the last snapshot of every series
// must be the same, bit for bit. Failures are reported to GoogleTest.
namespace cosim::testing {

// `cosim run <job> --output <output> [extra...]`, up to 10 minutes.
ProcessResult run_job(const std::filesystem::path& job, const std::filesystem::path& output,
                      const std::vector<std::string>& extra = {});

// The checkpoint directory of window `window` of a run.
std::filesystem::path checkpoint_of(const std::filesystem::path& run, std::size_t window);
// The names of a run's checkpoint directories, sorted.
std::vector<std::string> checkpoints_in(const std::filesystem::path& run);

// Every CSV of the uninterrupted run `whole` against the continued run's:
// the same header, and the same rows after the checkpoint (by the window
// when the first column is one, else by the time). Returns the rows compared.
std::size_t expect_same_continuation(const std::filesystem::path& whole,
                                     const std::filesystem::path& continued, std::size_t window,
                                     double time);

// The last snapshot of every series the continued run wrote against the
// uninterrupted run's: every dataset and attribute but the snapshot's index
// in its series. Returns the series compared.
std::size_t expect_same_last_snapshots(const std::filesystem::path& whole,
                                       const std::filesystem::path& continued);

// A run stopped by SIGTERM (a batch system's wall-time limit): `cosim run
// <job> --output <dir>/stopped --checkpoint-every 100000` (log in
// <dir>/stopped.log), signalled half a second after participant 'right'
// wrote its pid file. Returns its result and the window of the one
// checkpoint it wrote (0 and a test failure when it wrote another count).
struct StoppedRun {
  ProcessResult result;
  std::size_t window = 0;
};
StoppedRun stop_with_sigterm(const std::filesystem::path& dir, const std::filesystem::path& job);

// Runs `job` whole into <dir>/whole with a checkpoint every `every`, then
// from the checkpoint of `window` into <dir>/continued, and compares both.
void expect_restart_continues(const std::filesystem::path& dir, const std::filesystem::path& job,
                              const std::string& every, std::size_t window);

}  // namespace cosim::testing

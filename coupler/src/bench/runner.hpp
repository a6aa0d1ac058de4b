#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "bench/run_plan.hpp"

namespace cosim::bench {

// How one run ended, as `<run>/bench_run.json` records it. A run whose
// record has the key of its current inputs and state "completed" is not run
// again (a suite resumes where it stopped); any other is.
struct RunRecord {
  std::string key;
  std::string state = "pending";  // completed | failed | interrupted
  int exit_code = 0;
  double wall_time_s = 0.0;  // as the run measured itself (summary.json), else from outside
  std::string message;       // why it failed: exit status and the log's last lines
  bool reused = false;       // completed by an earlier `cosim bench`
  bool completed() const { return state == "completed"; }
};

struct RunnerOptions {
  int jobs = 1;
  bool terminal = false;  // progress rewritten in place on a terminal
  const std::atomic<bool>* interrupted = nullptr;
};

// Runs the planned runs, up to `jobs` at a time, each as a child process
// (`cosim run` or a standalone solver) whose console goes to
// `<run>/console.log`. Shows which runs are going, their simulated time and
// an ETA (read from each run's summary.json). On an interrupt every child is
// stopped and the unfinished runs are recorded as interrupted. Returns one
// record per run, in the plan's order.
std::vector<RunRecord> run_all(const std::vector<PlannedRun>& runs, const RunnerOptions& options);

// The record a run left, if any, with state "pending" when there is none.
RunRecord read_record(const PlannedRun& run);

}  // namespace cosim::bench

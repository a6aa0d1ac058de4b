#pragma once

#include <atomic>

#include "cosim/bench/run_plan.hpp"
#include "cosim/io/files.hpp"

// `cosim bench <suite.yaml> --output <dir>`: runs a suite's scenarios with
// each of their backends (resuming a partly finished suite), measures the
// metrics, and writes <dir>/results.csv, <dir>/report.md with its plots in
// <dir>/plots/, <dir>/summary.json and <dir>/log.txt.
namespace cosim::bench {

struct BenchRunOptions {
  BenchOptions bench;
  bool terminal = false;
  std::string verbosity = "normal";
  bool dry_run = false;  // write the inputs and list the runs, run nothing
  // A non-empty --output: refused, cleared (--overwrite) or resumed
  // (--resume: finished runs whose inputs did not change are kept).
  OutputReuse reuse = OutputReuse::refuse;
  const std::atomic<bool>* interrupted = nullptr;
};

// The exit code: 0 when every run finished (metrics outside tolerance are
// the report's business, not a failure of the bench), 3 when a run failed or
// the bench was interrupted; bad input throws InputError before anything runs.
int run_bench(const BenchRunOptions& options);

}  // namespace cosim::bench

#pragma once

#include <atomic>

#include "bench/run_plan.hpp"
#include "cosim/io/files.hpp"

// `cosim bench <suite.yaml> --output <dir>`: runs a suite's scenarios with
// each of their backends, measures the metrics, and writes <dir>/results.csv,
// <dir>/report.md with its plots in <dir>/plots/, <dir>/summary.json and
// <dir>/log.txt. A non-empty <dir> is refused unless --resume (a partly
// finished suite goes on: finished runs with unchanged inputs are kept) or
// --overwrite (cleared first); every run that runs starts in a cleared run
// directory.
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

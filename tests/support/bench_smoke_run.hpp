#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "bench/run_plan.hpp"
#include "bench/runner.hpp"

namespace cosim::testing {

// The outputs of one run of the bench-smoke test of `suite`
// (tests/bench_smoke): a validation test that checks a job the suite already
// runs, at the same resolution, reads that run instead of repeating it. Its
// CTest entry requires the fixture bench_smoke_<suite>, so CTest runs the
// suite first (also under `ctest -R <this test>`). Throws, naming the run,
// when the run is missing or did not complete.
inline std::filesystem::path bench_smoke_run(const std::string& suite, const std::string& scenario,
                                             const std::string& backend) {
  bench::PlannedRun run;
  run.directory = std::filesystem::path(COSIM_BINARY_DIR) / "test_runs" / ("bench_smoke_" + suite) /
                  "runs" / bench::directory_name(scenario) / backend;
  const bench::RunRecord record = bench::read_record(run);
  if (!record.completed())
    throw std::runtime_error(fmt::format(
        "run {}/{} of suite '{}' in {} is {} ({}): the bench-smoke test of the suite runs it "
        "(ctest -R bench_smoke_{})",
        scenario, backend, suite, run.directory.string(), record.state, record.message, suite));
  return run.output();
}

}  // namespace cosim::testing

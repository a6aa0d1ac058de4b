#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "run_process.hpp"

namespace cosim::testing {

// The outputs of one run of the bench-smoke test of `suite`
// (tests/bench_smoke): a validation test that checks a job the suite already
// runs, at the same resolution, reads that run instead of repeating it. Its
// CTest entry requires the fixture bench_smoke_<suite>, so CTest runs the
// suite first (also under `ctest -R <this test>`). Throws, naming the run,
// when the run is missing or did not complete.
inline std::filesystem::path bench_smoke_run(const std::string& suite, const std::string& scenario,
                                             const std::string& backend) {
  namespace fs = std::filesystem;
  const fs::path run = fs::path(COSIM_BINARY_DIR) / "test_runs" / ("bench_smoke_" + suite) /
                       "runs" / scenario / backend;
  const fs::path record = run / "bench_run.json";
  if (!fs::exists(record))
    throw std::runtime_error(fmt::format(
        "{} is missing: the bench-smoke test of suite '{}' runs it (ctest -R bench_smoke_{})",
        record.string(), suite, suite));
  const auto state = nlohmann::json::parse(read_text(record));
  if (state.value("state", "") != "completed")
    throw std::runtime_error(fmt::format("{}/{} of suite '{}' did not complete: {}", scenario,
                                         backend, suite, state.dump()));
  return run / "out";
}

}  // namespace cosim::testing

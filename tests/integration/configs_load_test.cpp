// Every YAML file shipped under configs/ loads: jobs through the coupler's
// loader (schema and cross-references), MPM (and depth-averaged),
// shallow-water, ICE and OpenFOAM cases through their solvers' loaders. A key
// renamed in a schema, or an example left behind by a change, fails here
// rather than in a user's first run. `kind: test_participant` files are read
// by the test participant, which the demo jobs run in cosim_run_test. Bench
// suites load, and every run they plan (at both resolutions) has a job and
// cases that load: the jobs the bench builds from its pairings and the cases
// its overrides change.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <string>

#include "bench/run_plan.hpp"
#include "bench/suite.hpp"
#include "ice/case/load_case.hpp"
#include "job/job.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/depth_averaged/depth_averaged_case.hpp"
#include "openfoam/case/load_case.hpp"
#include "swe/case/load_case.hpp"

namespace fs = std::filesystem;

namespace {

// Loads one job or case file by its kind; returns the kind.
std::string load_by_kind(const fs::path& file) {
  const std::string kind = YAML::LoadFile(file.string())["kind"].as<std::string>("");
  if (kind == "job") {
    (void)cosim::job::load_job(file);
  } else if (kind == "mpm_case") {
    (void)mpm::load_case(file);
  } else if (kind == "depth_averaged_case") {
    (void)mpm::load_depth_averaged_case(file);
  } else if (kind == "swe_case") {
    (void)swe::load_case(file);
  } else if (kind == "ice_case") {
    (void)ice::load_case(file);
  } else if (kind == "openfoam_case") {
    (void)openfoam::load_case(file);
  } else if (kind == "bench_suite") {
    (void)cosim::bench::load_suite(file);
  } else if (kind != "test_participant") {
    throw std::runtime_error("unknown kind '" + kind + "'");
  }
  return kind;
}

TEST(ShippedConfigs, EveryJobAndCaseLoads) {
  std::map<std::string, int> loaded;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(COSIM_SOURCE_DIR) / "configs")) {
    if (!entry.is_regular_file() || entry.path().extension() != ".yaml") continue;
    const fs::path& file = entry.path();
    SCOPED_TRACE(file.string());
    try {
      ++loaded[load_by_kind(file)];
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  for (const auto& [kind, count] : loaded) fmt::print("  {:17s} {} files load\n", kind, count);
  EXPECT_GE(loaded["job"], 9);
  EXPECT_GE(loaded["mpm_case"], 16);
  EXPECT_GE(loaded["depth_averaged_case"], 2);
  EXPECT_GE(loaded["swe_case"], 12);
  EXPECT_GE(loaded["ice_case"], 3);
  EXPECT_GE(loaded["openfoam_case"], 1);
  EXPECT_GE(loaded["bench_suite"], 4);
}

TEST(ShippedConfigs, EveryRunOfTheBenchSuitesHasInputsThatLoad) {
  const fs::path out =
      fs::temp_directory_path() / ("cosim_configs_load_bench_" + std::to_string(::getpid()));
  int runs = 0;
  for (const auto& entry :
       fs::directory_iterator(fs::path(COSIM_SOURCE_DIR) / "configs" / "bench")) {
    if (entry.path().extension() != ".yaml") continue;
    const auto suite = cosim::bench::load_suite(entry.path());
    for (auto resolution : {cosim::bench::Resolution::coarse, cosim::bench::Resolution::full}) {
      cosim::bench::BenchOptions options;
      options.output = out / suite.name / cosim::bench::to_string(resolution);
      options.resolution = resolution;
      for (const auto& run : cosim::bench::plan_runs(suite, options)) {
        SCOPED_TRACE(run.id() + " at " + cosim::bench::to_string(resolution));
        for (const auto& input : fs::directory_iterator(run.directory / "input")) {
          try {
            (void)load_by_kind(input.path());
          } catch (const std::exception& e) {
            ADD_FAILURE() << e.what();
          }
        }
        ++runs;
      }
    }
  }
  fs::remove_all(out);
  fmt::print("  {} bench runs have inputs that load\n", runs);
  EXPECT_GE(runs, 40);
}

}  // namespace

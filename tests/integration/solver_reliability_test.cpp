// Every solver executable keeps the same promises (architecture.md §6):
//   --validate loads and checks a case (its size against limits.memory_gib
//   included) without running or touching --output, and prints one line;
//   bad input, an absurd size among it, exits 2 naming the file, key and line;
//   a non-empty --output is refused before anything is written, and
//   --overwrite clears the earlier run it holds (OpenFOAM's case copy too);
//   summary.json states the run's size.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

#ifdef COSIM_TEST_OPENFOAM
#include "cosim/error.hpp"
#include "openfoam/foam/installation.hpp"
#endif

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

struct Solver {
  const char* program;
  const char* kind;
  const char* name;
  std::string text;      // a small case that runs in a few seconds
  const char* big_from;  // a replacement that makes it far too large
  const char* big_to;
  const char* snapshot;  // a snapshot file every run writes
};

const Solver mpm{"mpm_solver",
                 "mpm_case",
                 "drop",
                 R"(kind: mpm_case
name: drop
dimension: 2
grid: {origin: [0, 0], upper: [1, 1], cells: [20, 20]}
time: {end_time: 0.01}
gravity: [0, -9.81]
materials:
  rubber: {type: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}
bodies:
  - name: block
    material: rubber
    geometry: {box: {min: [0.4, 0.5], max: [0.6, 0.7]}}
    particles_per_cell: 2
output: {every: 0.005}
)",
                 "particles_per_cell: 2",
                 "particles_per_cell: 1000",
                 "particles_000001.h5"};

const Solver swe{"swe_fluid", "swe_case",          "dam",          R"(kind: swe_case
name: dam
dimension: 1
mesh: {from: 0.0, to: 4.0, cells: 80}
initial:
  depth: 0.1
  regions:
    - {box: {min: [0.0], max: [1.0]}, depth: 0.5}
time: {end_time: 0.05}
output: {every: 0.01}
)",
                 "cells: 80", "cells: 2000000000", "swe_000001.h5"};

const Solver ice{"ice_fluid",       "ice_case",        "column",
                 R"(kind: ice_case
name: column
dimension: 2
grid: {origin: [0.0, 0.0], upper: [0.2, 0.1], cells: [20, 10]}
gravity: [0.0, -9.81]
end_time: 0.005
materials:
  water:
    eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}
  air:
    eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}
exchange:
  - {materials: [water, air], momentum: 1.0e15}
initial:
  fill: air
  regions:
    - {box: {lower: [0.0, 0.0], upper: [0.05, 0.08]}, fill: water}
output: {every: 0.0025}
)", "cells: [20, 10]", "cells: [20000, 20000]",
                 "ice_000001.h5"};

const Solver openfoam{"openfoam_adapter",     "openfoam_case",  "tank",
                      R"(kind: openfoam_case
name: tank
generate:
  dimension: 2
  grid: {origin: [0.0, 0.0], upper: [0.2, 0.1], cells: [10, 5]}
  gravity: [0.0, -9.81]
  fluids:
    water: {density: 1000, viscosity: 1.0e-3}
    air: {density: 1, viscosity: 1.8e-5}
  water:
    - box: {lower: [0.0, 0.0], upper: [0.06, 0.06]}
  boundaries: {y_max: atmosphere}
end_time: 0.004
time_step: 1.0e-3
window: 0.002
output: {every: 0.002}
)", "cells: [10, 5]", "cells: [50000, 20000]",
                      "openfoam_000001.h5"};

std::string test_name(const ::testing::TestParamInfo<Solver>& info) {
  return info.param.program;
}

class SolverPromises : public ::testing::TestWithParam<Solver> {
 protected:
  void SetUp() override {
    // Every solver is built with the tests (fluid_adapters/CMakeLists.txt),
    // so a missing executable is a broken build, not a reason to skip.
    if (!fs::exists(binary(GetParam().program)))
      FAIL() << GetParam().program << " is not built in this tree";
    dir_ = fresh_directory(std::string("solver_promises_") + GetParam().program + "_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }

  ProcessResult solver(std::vector<std::string> args, const std::string& text) {
    write_text(dir_ / "case.yaml", text);
    args.insert(args.begin(),
                {binary(GetParam().program).string(), "--config", (dir_ / "case.yaml").string()});
    return run(args, std::chrono::seconds(120));
  }

  fs::path dir_;
};

TEST_P(SolverPromises, ValidatePrintsOneLineAndTouchesNothing) {
  const Solver& s = GetParam();
  const ProcessResult r = solver({"--validate", "--output", (dir_ / "out").string()}, s.text);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, StartsWith(fmt::format("{}: valid {} '{}': ", (dir_ / "case.yaml").string(),
                                               s.kind, s.name)));
  EXPECT_THAT(r.output,
              ::testing::AnyOf(HasSubstr(" cells, about "), HasSubstr(" grid nodes, about ")));
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_P(SolverPromises, ValidateRefusesAnUnknownKeyAtItsLine) {
  const ProcessResult r = solver({"--validate"}, GetParam().text + "thread: 2\n");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("case.yaml:"));
  EXPECT_THAT(r.output, HasSubstr("unknown key 'thread'"));
}

TEST_P(SolverPromises, AnAbsurdSizeExitsTwoWithTheEstimateAtOnce) {
  const Solver& s = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r =
      solver({"--output", (dir_ / "out").string()}, replaced(s.text, s.big_from, s.big_to));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("key 'limits.memory_gib': the run would need about"));
  EXPECT_THAT(r.output, HasSubstr("raise limits.memory_gib"));
  const ProcessResult v = solver({"--validate"}, replaced(s.text, s.big_from, s.big_to));
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_THAT(v.output, HasSubstr("the run would need about"));
}

TEST_P(SolverPromises, AnAbsurdOutputIntervalExitsTwoAtItsKey) {
  std::string text = GetParam().text;
  const auto at = text.find("output: {every: ");
  ASSERT_NE(at, std::string::npos);
  text = text.substr(0, at) + "output: {every: 1.0e-300}\n";
  const ProcessResult r = solver({"--output", (dir_ / "out").string()}, text);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("key 'output.every': an interval of 1e-300 s gives"));
}

// Before: a second run into the same directory mixed with the first (stale
// snapshots of a longer run stayed).
TEST_P(SolverPromises, ANonEmptyOutputIsRefusedBeforeAnythingIsWritten) {
  const fs::path out = dir_ / "out";
  write_text(out / "summary.json", "{\"program\": \"an earlier run\"}");
  const ProcessResult r = solver({"--output", out.string()}, GetParam().text);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("is not empty"));
  EXPECT_THAT(r.output, HasSubstr("--overwrite"));
  EXPECT_EQ(read_text(out / "summary.json"), "{\"program\": \"an earlier run\"}");
  EXPECT_FALSE(fs::exists(out / "log.txt"));
}

TEST_P(SolverPromises, OverwriteClearsTheEarlierRunAndTheSummaryStatesTheSize) {
  const Solver& s = GetParam();
#ifdef COSIM_TEST_OPENFOAM
  if (std::string(s.program) == "openfoam_adapter") {
    try {
      openfoam::find_installation({"interFoam", "blockMesh", "setFields", "postProcess"});
    } catch (const cosim::Error& e) {
      // Skipped only on a machine without OpenFOAM, where the adapter has no
      // solver to run; .ci/setup installs it, so in CI this case always runs.
      GTEST_SKIP() << "OpenFOAM is not installed: " << e.what();
    }
  }
#endif
  const fs::path out = dir_ / "out";
  write_text(out / "summary.json", "{}");
  write_text(out / "snapshot_000099.h5", "stale");
  write_text(out / "case" / "processor0" / "9" / "U", "stale");  // an OpenFOAM case copy
  const ProcessResult r = solver({"--output", out.string(), "--overwrite"}, s.text);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "snapshot_000099.h5"));
  EXPECT_FALSE(fs::exists(out / "case" / "processor0"));
  EXPECT_TRUE(fs::exists(out / s.snapshot));
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["program"], s.program);
  EXPECT_GT(summary["size"]["memory_bytes_estimate"].get<double>(), 1e6);
  EXPECT_DOUBLE_EQ(summary["size"]["memory_limit_bytes"].get<double>(), 8.0 * (1 << 30));
  // --overwrite never clears the directory that holds the case file.
  const ProcessResult self =
      run({binary(s.program).string(), "--config", (dir_ / "case.yaml").string(), "--output",
           dir_.string(), "--overwrite"},
          std::chrono::seconds(60));
  EXPECT_EQ(self.exit_code, 2) << self.output;
  EXPECT_THAT(self.output, HasSubstr("which holds the case file"));
  EXPECT_TRUE(fs::exists(dir_ / "case.yaml"));
}

INSTANTIATE_TEST_SUITE_P(Solvers, SolverPromises, ::testing::Values(mpm, swe, ice, openfoam),
                         test_name);

// Started by `cosim run` (its endpoint options given), a solver writes into
// the run directory the coupler prepared, where the coupler's console.log
// already is. (No coupler answers here: the run ends when it gives up
// connecting, not at the directory.)
TEST(SolverUnderCosimRun, UsesTheDirectoryTheCouplerPrepared) {
  const fs::path dir = fresh_directory("solver_promises_under_cosim_run");
  write_text(dir / "case.yaml", swe.text);
  write_text(dir / "water" / "console.log", "the coupler's console\n");
  const ProcessResult r =
      run({binary("swe_fluid").string(), "--config", (dir / "case.yaml").string(), "--output",
           (dir / "water").string(), "--cosim-endpoint", "ipc://" + (dir / "none.sock").string(),
           "--cosim-name", "water", "--cosim-connect-timeout", "0.2"},
          std::chrono::seconds(60));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("is not empty"))) << r.output;
  EXPECT_THAT(read_text(dir / "water" / "console.log"), StartsWith("the coupler's console\n"));
  EXPECT_TRUE(fs::exists(dir / "water" / "summary.json"));
}

}  // namespace
}  // namespace cosim::testing

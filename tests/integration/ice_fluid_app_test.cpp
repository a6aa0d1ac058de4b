// End to end: the `ice_fluid` executable standalone: what a good run leaves
// behind, exit 2 with a located message for bad input, exit 4 for a
// numerical failure.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// A small water column in air; line numbers matter.
const char* const column_case = R"(kind: ice_case
name: column
dimension: 2
grid: {origin: [0.0, 0.0], upper: [0.2, 0.1], cells: [20, 10]}
gravity: [0.0, -9.81]
end_time: 0.05
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
output:
  every: 0.01
  gauges: [{name: toe, point: [0.06, 0.005]}]
)";

ProcessResult run_case(const fs::path& dir, const std::string& text) {
  write_text(dir / "case.yaml", text);
  return run({binary("ice_fluid").string(), "--config", (dir / "case.yaml").string(), "--output",
              (dir / "run").string(), "--verbosity", "quiet"},
             std::chrono::seconds(120));
}

TEST(IceFluidApp, LeavesSnapshotsGaugesAndASummary) {
  const fs::path dir = fresh_directory("ice_fluid_app_good");
  const ProcessResult r = run_case(dir, column_case);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path out = dir / "run";
  EXPECT_TRUE(fs::exists(out / "ice.xdmf"));
  EXPECT_TRUE(fs::exists(out / "ice_000005.h5"));
  EXPECT_TRUE(fs::exists(out / "log.txt"));
  const auto gauges =
      read_csv(out / "gauges.csv");  // time, p, ux, uy, water_fraction, air_fraction
  ASSERT_GT(gauges.size(), 10u);
  ASSERT_EQ(gauges.back().size(), 6u);
  EXPECT_NEAR(gauges.back()[0], 0.05, 1e-12);
  EXPECT_GT(gauges.back()[4], 0.5) << "the water reached the gauge beside the column";
  EXPECT_EQ(read_csv(out / "steps.csv").size(), 6u);  // t = 0, 0.01, ..., 0.05
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_EQ(summary["program"], "ice_fluid");
  for (const char* total : {"mass_water", "mass_air"}) {
    EXPECT_LT(std::abs(summary["conserved"][total]["relative_change"].get<double>()), 1e-12)
        << total;
  }
  EXPECT_EQ(summary["case"]["cells"], 200);
  EXPECT_GT(summary["metrics"]["mean_cg_iterations"]["value"].get<double>(), 0.0);
}

TEST(IceFluidApp, ListsItsKeys) {
  const ProcessResult r =
      run({binary("ice_fluid").string(), "--help-config"}, std::chrono::seconds(30));
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("minimum_volume_fraction"));
  EXPECT_THAT(r.output, HasSubstr("linear_water"));
}

TEST(IceFluidApp, BadInputExitsTwoNamingFileKeyAndLine) {
  const struct {
    const char* from;
    const char* to;
    const char* expected;
  } cases[] = {
      {"fill: water}", "fill: steam}", "case.yaml:17"},
      {"momentum: 1.0e15", "momentum: -1", "exchange"},
      {"cells: [20, 10]", "cells: [20]", "grid.cells"},
  };
  for (const auto& c : cases) {
    const fs::path dir = fresh_directory("ice_fluid_app_bad");
    const ProcessResult r = run_case(dir, replaced(column_case, c.from, c.to));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.expected));
    EXPECT_TRUE(fs::exists(dir / "run" / "summary.json"));
  }
}

// Options PETSc refuses are the case's bad input, in PETSc's words.
TEST(IceFluidApp, PetscOptionsPetscRefusesExitTwoNamingTheKey) {
  const fs::path dir = fresh_directory("ice_fluid_app_bad_petsc_options");
  const ProcessResult r = run_case(dir, std::string(column_case) +
                                            "numerics: {pressure: {solver: petsc, petsc_options: "
                                            "\"-ice_pressure_pc_pfmg_relax_type bogus\"}}\n");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("case.yaml: key 'numerics.pressure.petsc_options': PETSc "
                                  "refused the options \"-ice_pressure_pc_pfmg_relax_type "
                                  "bogus\": Unknown option bogus"));
  EXPECT_THAT(r.output, HasSubstr("Available options: jacobi"));
}

// An option PETSc never reads (misspelled, or another preconditioner's) is
// named in a warning after the first solve; the run goes on.
TEST(IceFluidApp, PetscOptionsPetscNeverReadsAreNamedInAWarning) {
  const fs::path dir = fresh_directory("ice_fluid_app_unused_petsc_options");
  const ProcessResult r = run_case(
      dir, replaced(std::string(column_case), "end_time: 0.05", "end_time: 0.001") +
               "numerics: {pressure: {solver: petsc, petsc_options: "
               "\"-ice_pressure_ksp_monitr -ice_pressure_pc_hypre_boomeramg_strong_threshold "
               "0.5\"}}\n");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("numerics.pressure.petsc_options: PETSc did not use "
                        "-ice_pressure_ksp_monitr, -ice_pressure_pc_hypre_boomeramg_strong_"
                        "threshold 0.5 (misspelled, or an option of another preconditioner than "
                        "pfmg)"));
}

// The column case with its first step and step floor, run in `dir`.
ProcessResult run_with_steps(const fs::path& dir, const char* initial, const char* floor) {
  return run_case(dir, std::string(column_case) + "numerics: {initial_time_step: " + initial +
                           ", min_time_step: " + floor + "}\n");
}

TEST(IceFluidApp, NumericalFailureExitsFour) {
  // A step floor above any step the flow allows.
  const ProcessResult r =
      run_with_steps(fresh_directory("ice_fluid_app_numerical"), "1.0e-2", "1.0e-2");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_THAT(r.output, HasSubstr("min_time_step"));
}

TEST(IceFluidApp, AFailureAfterSomeStepsLeavesTheStateItFailedFromAsALastSnapshot) {
  // The collapsing column's flow soon needs steps below 4 ms (at t = 0.025 s):
  // snapshots at 0, 0.01 and 0.02 s, then the state the steps were refused from.
  const fs::path dir = fresh_directory("ice_fluid_app_failure_snapshot");
  const ProcessResult r = run_with_steps(dir, "1.0e-2", "4.0e-3");
  ASSERT_EQ(r.exit_code, 4) << r.output;
  const fs::path out = dir / "run";
  EXPECT_TRUE(fs::exists(out / "ice_000003.h5"));
  EXPECT_FALSE(fs::exists(out / "ice_000004.h5"));
  EXPECT_THAT(read_text(out / "ice.xdmf"), HasSubstr("ice_000003.h5"));
  EXPECT_THAT(read_text(out / "log.txt"), HasSubstr("where the steps were refused, is snapshot 3"));
}

TEST(IceFluidApp, AStepCutShortByAnOutputTimeMayBeShorterThanTheFloor) {
  // 2 ms steps reach 0.039 s; the step to the snapshot at 0.04 s is 0.76 ms,
  // below the 1 ms floor, which is on the steps the stability allows.
  const fs::path dir = fresh_directory("ice_fluid_app_cut_step");
  const ProcessResult r = run_with_steps(dir, "2.0e-3", "1.0e-3");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_csv(dir / "run" / "steps.csv").size(), 6u);
}

}  // namespace
}  // namespace cosim::testing

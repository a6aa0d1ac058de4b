// End to end: the `swe_fluid` executable standalone and as the water of a
// short coupled job: what a good run leaves behind, exit 2 with a located
// message for bad input.

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

// A small dam break onto a dry bed with a bump; line numbers matter.
const char* const dam_case = R"(kind: swe_case
name: dam
dimension: 1
mesh: {from: 0.0, to: 4.0, cells: 80}
bed: {bumps: [{centre: [2.5], radius: 0.5, height: 0.2}]}
initial:
  depth: 0.0
  regions:
    - {box: {min: [0.0], max: [1.0]}, depth: 0.5}
boundaries: {left: wall, right: wall}
time: {end_time: 0.5}
output:
  every: 0.1
  gauges:
    - {name: bump, x: 2.5}
)";

ProcessResult run_case(const fs::path& dir, const std::string& text) {
  write_text(dir / "case.yaml", text);
  return run({binary("swe_fluid").string(), "--config", (dir / "case.yaml").string(), "--output",
              (dir / "run").string(), "--verbosity", "quiet"},
             std::chrono::seconds(120));
}

TEST(SweFluidApp, LeavesSnapshotsGaugesAndASummary) {
  const fs::path dir = fresh_directory("swe_fluid_app_good");
  const ProcessResult r = run_case(dir, dam_case);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path out = dir / "run";
  EXPECT_TRUE(fs::exists(out / "swe.xdmf"));
  EXPECT_TRUE(fs::exists(out / "swe_000005.h5"));
  EXPECT_TRUE(fs::exists(out / "log.txt"));
  const auto gauges = read_csv(out / "gauges.csv");  // rows: time, eta, h, speed; every step
  ASSERT_GT(gauges.size(), 10u);
  ASSERT_EQ(gauges.back().size(), 4u);
  EXPECT_NEAR(gauges.back()[0], 0.5, 1e-9);
  EXPECT_GT(gauges.back()[2], 0.0) << "the water reached the bump";
  const auto water = read_csv(out / "water.csv");
  ASSERT_EQ(water.size(), 6u);                                    // t = 0, 0.1, ..., 0.5
  for (const auto& row : water) EXPECT_NEAR(row[1], 0.5, 1e-13);  // volume, walls all round
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_EQ(summary["program"], "swe_fluid");
  EXPECT_LT(std::abs(summary["conserved"]["water_volume"]["relative_change"].get<double>()), 1e-13);
  EXPECT_GT(summary["steps"].get<int>(), 10);
  EXPECT_EQ(summary["case"]["cells"], 80);
}

TEST(SweFluidApp, ListsItsKeys) {
  const ProcessResult r =
      run({binary("swe_fluid").string(), "--help-config"}, std::chrono::seconds(30));
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("bed_pressure"));
  EXPECT_THAT(r.output, HasSubstr("mesh.segments"));
}

struct BadInput {
  const char* name;
  const char* from;
  const char* to;
  const char* expected;
};

class SweFluidBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SweFluidBadInput, ExitsTwoNamingTheKeyAndLine) {
  const BadInput& bad = GetParam();
  const fs::path dir = fresh_directory(std::string("swe_fluid_bad_") + bad.name);
  const ProcessResult r = run_case(dir, replaced(dam_case, bad.from, bad.to));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(bad.expected));
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 2);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SweFluidBadInput,
    ::testing::Values(
        BadInput{"negative_depth", "depth: 0.5}", "depth: -0.5}", "case.yaml:9:"},
        BadInput{"zero_width", "mesh: {from: 0.0, to: 4.0, cells: 80}",
                 "mesh: {from: 4.0, to: 4.0, cells: 80}",
                 "key 'mesh.to': the line has zero or negative length"},
        BadInput{"no_cells", "cells: 80}", "cells: 0}", "key 'mesh.cells'"},
        BadInput{"gauge_outside", "x: 2.5}", "x: 4.5}", "case.yaml:15:"},
        BadInput{"bed_profile_short", "bed: {bumps",
                 "bed: {profile: [[1.0, 0.0], [4.0, 0.0]], bumps", "key 'bed.profile'"},
        BadInput{"unknown_key", "time: {end_time: 0.5}", "time: {end_tme: 0.5}", "end_tme"}),
    [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace cosim::testing

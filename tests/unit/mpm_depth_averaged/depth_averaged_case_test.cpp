// The `kind: depth_averaged_case` file: what it reads, what it refuses (with
// file, key and line), and what a run writes.

#include "mpm/depth_averaged/depth_averaged_case.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "input_error.hpp"
#include "mpm/depth_averaged/depth_averaged_run.hpp"
#include "replaced_text.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace mpm {
namespace {

using cosim::testing::input_error_from;
using cosim::testing::replaced;
using ::testing::HasSubstr;

constexpr double deg = std::numbers::pi / 180.0;

const char* const dam_break = R"(kind: depth_averaged_case
name: dam_break
grid: {origin: [-10, 0], cells: [60, 4], spacing: [0.5, 0.5]}
terrain: {inclination: 22}
time: {end_time: 1.0}
materials:
  sand:
    density: 2000
    internal_friction_angle: 30
    basal_friction_angle: 21
    cohesion: 500
    cohesion_degradation: {critical_volumetric_strain: 0.05}
masses:
  - name: reservoir
    material: sand
    region: {box: {min: [-5, 0], max: [0, 2]}}
    depth: 1.0
gauges:
  - {name: below, position: [2, 1]}
output: {every: 0.5}
threads: 1
)";

DepthAveragedCase load(const std::string& text) {
  return load_depth_averaged_case_text(text, "case.yaml");
}

TEST(DepthAveragedCase, ReadsTheGroundTheMaterialsAndSeedsTheMasses) {
  const DepthAveragedCase c = load(dam_break);
  EXPECT_EQ(c.name, "dam_break");
  EXPECT_EQ(c.settings.grid.cells[0], 60);
  EXPECT_NEAR(c.settings.terrain.inclination(), 22 * deg, 1e-15);
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_NEAR(c.materials[0].basal_friction_angle, 21 * deg, 1e-15);
  EXPECT_TRUE(c.materials[0].degradation.enabled());
  EXPECT_EQ(c.materials[0].basal_pressure_factor, 1.0);
  EXPECT_EQ(c.settings.earth_pressure.model(), EarthPressureModel::rankine);
  // 10 x 4 cells of 0.5 m, 2 x 2 points each, holding the 5 x 2 x 1 m^3
  EXPECT_EQ(c.particles.size(), 160u);
  double volume = 0;
  for (double v : c.particles.volume) volume += v;
  EXPECT_NEAR(volume, 10.0, 1e-12);
  EXPECT_NEAR(c.particles.total_mass(), 2e4, 1e-8);
  ASSERT_EQ(c.gauges.size(), 1u);
  EXPECT_EQ(c.gauges[0].name, "below");
  EXPECT_EQ(c.end_time, 1.0);
}

TEST(DepthAveragedCase, APolygonHoldsOnlyThePointsInsideIt) {
  const DepthAveragedCase c = load(replaced(dam_break, "region: {box: {min: [-5, 0], max: [0, 2]}}",
                                            "region: {polygon: [[-5, 0], [0, 0], [-5, 2]]}"));
  for (const auto& x : c.particles.position) EXPECT_LT(x[0] / 5.0 + 1.0 + x[1] / 2.0, 1.0 + 1e-12);
  EXPECT_GT(c.particles.size(), 50u);
  EXPECT_LT(c.particles.size(), 110u);
}

TEST(DepthAveragedCase, ADepthRasterGivesEachPointItsDepth) {
  const cosim::testing::ScratchDirectory dir;
  dir.write("depth.asc",
            "ncols 3\nnrows 2\nxllcorner -6\nyllcorner 0\ncellsize 2\n"
            "1 2 3\n1 2 3\n");
  const auto file =
      dir.write("case.yaml", replaced(dam_break, "depth: 1.0", "depth: {raster: depth.asc}"));
  const DepthAveragedCase c = load_depth_averaged_case(file);
  for (std::size_t p = 0; p < c.particles.size(); ++p) {
    // bilinear between the centres x = -5, -3, -1 at 1, 2, 3 m
    const double expected = std::clamp(1.0 + (c.particles.position[p][0] + 5.0) / 2.0, 1.0, 3.0);
    EXPECT_NEAR(c.particles.depth(p), expected, 1e-12);
  }
}

TEST(DepthAveragedCase, RefusesWhatItCannotRunAtTheKeyAndLine) {
  struct Bad {
    std::string from, to, says;
  };
  const Bad cases[] = {
      {"    basal_friction_angle: 21", "    basal_friction_angel: 21", "basal_friction_angel"},
      {"    material: sand", "    material: snad", "unknown material 'snad'"},
      {"max: [0, 2]", "max: [0, 20]", "outside the grid"},
      {"depth: 1.0", "depth: -1.0", "depth"},
      {"position: [2, 1]", "position: [50, 1]", "outside the grid"},
      {"spacing: [0.5, 0.5]", "spacing: [0.5, 0.5], upper: [20, 2]", "exactly one of"},
      {"    cohesion: 500", "    basal_pressure_factor: 2", "basal_pressure_factor"},
      {"    cohesion_degradation: {critical_volumetric_strain: 0.05}",
       "    fragmentation_strain: 0.1", "needs `cohesion_degradation`"},
      {"output: {every: 0.5}", "output: {every: 1.0e-9}", "more than"},
  };
  for (const auto& bad : cases) {
    const std::string text = replaced(dam_break, bad.from, bad.to);
    ASSERT_NE(text, dam_break) << bad.from;
    const auto error = input_error_from([&] { load(text); });
    EXPECT_THAT(error.what(), HasSubstr(bad.says)) << bad.to;
    EXPECT_THAT(error.what(), HasSubstr("case.yaml:")) << bad.to;
    EXPECT_GT(error.where().line, 0) << bad.to;
  }
}

TEST(DepthAveragedCase, RefusesRastersThatDoNotCoverOrHoldNegativeDepths) {
  const cosim::testing::ScratchDirectory dir;
  dir.write("small_bed.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n0 0\n0 0\n");
  auto file =
      dir.write("bed.yaml", replaced(dam_break, "terrain: {inclination: 22}",
                                     "terrain: {inclination: 22, bed: {raster: small_bed.asc}}"));
  auto error = input_error_from([&] { load_depth_averaged_case(file); });
  EXPECT_THAT(error.what(), HasSubstr("does not cover the ground grid"));
  EXPECT_THAT(error.what(), HasSubstr("bed.yaml:4:"));

  dir.write("negative.asc",
            "ncols 3\nnrows 2\nxllcorner -6\nyllcorner 0\ncellsize 2\n1 -2 3\n1 2 3\n");
  file = dir.write("negative.yaml",
                   replaced(dam_break, "depth: 1.0", "depth: {raster: negative.asc}"));
  error = input_error_from([&] { load_depth_averaged_case(file); });
  EXPECT_THAT(error.what(), HasSubstr("negative depth -2"));
}

TEST(DepthAveragedCase, ARunWritesPointsGroundGaugesAndASummaryAndKeepsTheMass) {
  const cosim::testing::ScratchDirectory dir;
  RunOptions options;
  options.config = dir.write("case.yaml", dam_break);
  options.output = dir / "run";
  options.verbosity = cosim::Verbosity::quiet;
  ASSERT_EQ(run_depth_averaged_case(options), 0);
  for (const char* file : {"points.xdmf", "ground.xdmf", "points_000002.h5", "ground_000002.h5",
                           "gauges.csv", "summary.json", "log.txt"})
    EXPECT_TRUE(std::filesystem::exists(options.output / file)) << file;
  const auto rows = cosim::testing::read_csv(options.output / "gauges.csv");
  ASSERT_EQ(rows.size(), 3u);  // 0, 0.5 and 1 s
  EXPECT_NEAR(rows[2][0], 1.0, 1e-12);
  EXPECT_GT(rows[2][1], 0.0) << "the mass reaches the gauge 2 m below the gate within 1 s";
  const auto summary =
      nlohmann::json::parse(cosim::testing::read_text(options.output / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 0);
  EXPECT_NEAR(summary["conserved"]["mass"]["relative_change"].get<double>(), 0.0, 1e-14);
  EXPECT_GT(summary["metrics"]["front_x"]["value"].get<double>(), 2.0);
  EXPECT_NEAR(summary["metrics"]["simulated_time"]["value"].get<double>(), 1.0, 1e-12);
}

TEST(DepthAveragedCase, ARunThatLeavesTheGridStopsWithExitFourAndKeepsItsSnapshots) {
  const cosim::testing::ScratchDirectory dir;
  RunOptions options;
  options.config = dir.write("case.yaml", replaced(dam_break, "end_time: 1.0", "end_time: 30"));
  options.output = dir / "run";
  options.verbosity = cosim::Verbosity::quiet;
  EXPECT_EQ(run_depth_averaged_case(options), 4);
  EXPECT_TRUE(std::filesystem::exists(options.output / "points_000000.h5"));
  const auto summary =
      nlohmann::json::parse(cosim::testing::read_text(options.output / "summary.json"));
  EXPECT_EQ(summary["status"]["exit_code"], 4);
  EXPECT_THAT(summary["status"]["message"].get<std::string>(), HasSubstr("left the grid"));
}

}  // namespace
}  // namespace mpm

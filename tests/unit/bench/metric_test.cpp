#include "bench/metric.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "bench/analytic_solution.hpp"
#include "bench/darcy_column.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;

MetricSpec metric(const std::string& reference_yaml, const std::string& norm = "relative") {
  MetricSpec m;
  m.name = "m";
  const YAML::Node r = YAML::Load(reference_yaml);
  m.reference.params = r;
  m.reference.kind =
      r["value"] ? "value" : (r["analytic"] ? "analytic" : (r["csv"] ? "csv" : "none"));
  m.error.norm = norm;
  return m;
}

Measurement number(double v) {
  Measurement m;
  m.value = v;
  return m;
}

Measurement curve(std::vector<double> x, std::vector<double> y, std::string abscissa = "t [s]") {
  Measurement m;
  m.x = std::move(x);
  m.y = std::move(y);
  m.abscissa = std::move(abscissa);
  return m;
}

TEST(Metric, ANumberAgainstAValueIsJudgedByItsTolerance) {
  MetricSpec m = metric("{value: 2.0}");
  m.tolerance = 0.1;
  MetricResult r = evaluate(m, "ice", number(2.1));
  EXPECT_NEAR(*r.error, 0.05, 1e-15);
  EXPECT_EQ(r.verdict, Verdict::pass);
  r = evaluate(m, "ice", number(2.5));
  EXPECT_EQ(r.verdict, Verdict::fail);
  m.error.norm = "absolute";
  EXPECT_NEAR(*evaluate(m, "ice", number(2.5)).error, 0.5, 1e-15);
  m.tolerance.reset();
  EXPECT_EQ(evaluate(m, "ice", number(2.5)).verdict, Verdict::measured);
}

TEST(Metric, AToleranceMayBeGivenPerBackend) {
  MetricSpec m = metric("{value: 1.0}");
  m.backend_tolerances["ice"] = 0.01;
  EXPECT_EQ(evaluate(m, "ice", number(1.5)).verdict, Verdict::fail);
  EXPECT_EQ(evaluate(m, "openfoam", number(1.5)).verdict, Verdict::measured);
}

TEST(Metric, AnAnalyticNumberIsTheSolutionsValue) {
  const MetricSpec m = metric(
      "{analytic: darcy_pore_velocity, parameters: {solid_fraction: 0.6, pressure_drop: 50662.5, "
      "grain_size: 1.0e-3, length: 1.0}}");
  const double exact = DarcyColumn{1e-3, 1e-3, 1.0}.pore_velocity(0.6, 50662.5);
  const MetricResult r = evaluate(m, "ice", number(exact * 1.01));
  EXPECT_NEAR(*r.reference, exact, 1e-15 * exact);
  EXPECT_NEAR(*r.error, 0.01, 1e-12);
}

TEST(Metric, ACurveAgainstAnAnalyticCurveAtItsSnapshotsTime) {
  // Still water 1 m deep: p = rho g (1 - y).
  const MetricSpec m0 = metric(
      "{analytic: hydrostatic_pressure, parameters: {surface: 1.0, density: 1000}}", "max_abs");
  MetricSpec m = m0;
  m.error.scale = 9810.0;
  Measurement c = curve({0.0, 0.5, 1.0}, {9810.0, 4905.0 + 98.1, 0.0}, "y [m]");
  const MetricResult r = evaluate(m, "ice", c);
  EXPECT_NEAR(*r.error, 0.01, 1e-12);
  EXPECT_FALSE(r.value.has_value());  // a curve against a reference is summed up by its error
  ASSERT_EQ(r.reference_x.size(), 3u);
  EXPECT_DOUBLE_EQ(r.reference_y[0], 9810.0);
  m.error.norm = "mean_abs";
  EXPECT_NEAR(*evaluate(m, "ice", c).error, 98.1 / 3 / 9810.0, 1e-12);
  m.error.norm = "relative_l1";
  m.error.scale = 1.0;
  EXPECT_NEAR(*evaluate(m, "ice", c).error, 98.1 / (9810.0 + 4905.0), 1e-12);
  m.error.norm = "max_abs";
  m.error.window = std::make_pair(0.6, 1.0);
  EXPECT_NEAR(*evaluate(m, "ice", c).error, 0.0, 1e-15);  // only y = 1 in the window
}

TEST(Metric, ACurveAgainstAFileSelectsRowsByText) {
  ScratchDirectory dir;
  const auto file =
      dir.write("front.csv", "# comment\nkind,T,Z\nfront,1,2\nfront,2,3\nheight,1,9\n");
  MetricSpec m =
      metric("{csv: " + file.string() + ", x: T, y: Z, where: {kind: front}}", "max_relative");
  m.reference.csv = file;
  // The simulated front runs 10 % ahead at T = 1 and on time at T = 2.
  const MetricResult r = evaluate(m, "ice", curve({0.0, 1.0, 2.0}, {1.0, 2.2, 3.0}));
  EXPECT_NEAR(*r.error, 0.1, 1e-12);
  EXPECT_EQ(r.reference_x, (std::vector<double>{1.0, 2.0}));
}

TEST(Metric, TheSpeedAndTheFittedOffsetOfASeries) {
  ScratchDirectory dir;
  const auto file = dir.write("front.csv", "T,Z\n1,1\n2,2\n3,3\n");
  MetricSpec m = metric("{csv: " + file.string() + ", x: T, y: Z}", "speed");
  m.reference.csv = file;
  // The same front 0.2 ahead in time, at the same speed.
  const Measurement ahead = curve({0.0, 1.0, 2.0, 3.0, 4.0}, {0.2, 1.2, 2.2, 3.2, 4.2});
  EXPECT_NEAR(*evaluate(m, "ice", ahead).error, 0.0, 1e-12);
  m.error.norm = "max_relative_offset_fitted";
  m.error.offsets = {0.0, 0.4};
  const MetricResult r = evaluate(m, "ice", ahead);
  EXPECT_NEAR(*r.error, 0.0, 1e-9);
  EXPECT_NE(r.note.find("offset 0.2"), std::string::npos) << r.note;
  m.error.norm = "max_relative";
  EXPECT_NEAR(*evaluate(m, "ice", ahead).error, 0.2, 1e-12);
}

TEST(Metric, AMissingReferenceMakesTheResultUnavailableNotFatal) {
  MetricSpec m = metric("{csv: /nowhere/ref.csv, column: v}");
  m.reference.csv = "/nowhere/ref.csv";
  const MetricResult r = evaluate(m, "ice", number(1.0));
  EXPECT_EQ(r.verdict, Verdict::unavailable);
  EXPECT_NE(r.note.find("/nowhere/ref.csv"), std::string::npos);
}

TEST(Metric, InterpolationHoldsTheEnds) {
  const std::vector<double> x{0.0, 1.0}, y{0.0, 2.0};
  EXPECT_DOUBLE_EQ(interpolate(x, y, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(interpolate(x, y, -1.0), 0.0);
  EXPECT_DOUBLE_EQ(interpolate(x, y, 5.0), 2.0);
}

TEST(AnalyticSolutions, AreTheReferencesTheyName) {
  const AnalyticSolution* stoker = find_analytic_solution("dam_break_depth");
  ASSERT_NE(stoker, nullptr);
  const Parameters p =
      stoker->with_defaults({{"left_depth", 1.0}, {"right_depth", 0.5}, {"dam_position", 0.5}});
  EXPECT_DOUBLE_EQ(stoker->value(p, 0.0, 0.1), 1.0);      // upstream of the rarefaction
  EXPECT_DOUBLE_EQ(stoker->value(p, 1.0, 0.1), 0.5);      // ahead of the bore
  EXPECT_NEAR(stoker->value(p, 0.6, 0.1), 0.7275, 1e-3);  // Stoker's middle state
  const AnalyticSolution* sod = find_analytic_solution("shock_tube_density");
  ASSERT_NE(sod, nullptr);
  const Parameters q = sod->with_defaults({{"left_density", 1.0},
                                           {"left_pressure", 1.0},
                                           {"right_density", 0.125},
                                           {"right_pressure", 0.1},
                                           {"diaphragm", 0.5}});
  EXPECT_DOUBLE_EQ(sod->value(q, 0.1, 0.2), 1.0);
  EXPECT_DOUBLE_EQ(sod->value(q, 0.95, 0.2), 0.125);
  EXPECT_NEAR(sod->value(q, 0.8, 0.2), 0.2656, 1e-3);  // Toro's shocked state
  const AnalyticSolution* terzaghi = find_analytic_solution("terzaghi_excess_pressure");
  ASSERT_NE(terzaghi, nullptr);
  const Parameters t = terzaghi->with_defaults(
      {{"height", 1.0}, {"load", 1.0e4}, {"consolidation_coefficient", 1.0}});
  EXPECT_NEAR(terzaghi->value(t, 0.0, 1e-6), 1.0e4, 1.0);  // undrained at the bottom at first
  EXPECT_NEAR(terzaghi->value(t, 1.0, 0.5), 0.0, 1e-9);    // drained at the top
  EXPECT_EQ(find_analytic_solution("nothing"), nullptr);
  EXPECT_NE(analytic_solutions_help().find("hydrostatic_pressure"), std::string::npos);
}

}  // namespace
}  // namespace cosim::bench

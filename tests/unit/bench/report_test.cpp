#include "bench/report.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "cosim/io/csv_table.hpp"
#include "registered_backend.hpp"
#include "scratch_directory.hpp"

namespace cosim::bench {
namespace {

using cosim::testing::ScratchDirectory;
using testing::backend;

struct TwoBackends {
  Suite suite;
  std::vector<PlannedRun> runs;
  std::vector<RunResult> results;

  TwoBackends() {
    Scenario s;
    s.name = "column";
    s.title = "A column";
    MetricSpec m;
    m.name = "speed";
    m.label = "speed |u|";
    m.unit = "m/s";
    m.reference.kind = "value";
    s.metrics.push_back(m);
    BackendRuns ice, foam;
    ice.backend = &backend("ice");
    foam.backend = &backend("openfoam");
    s.backends = {ice, foam};
    suite.name = "small";
    suite.title = "Small";
    suite.scenarios.push_back(s);
    const Scenario& scenario = suite.scenarios[0];
    for (const auto& b : scenario.backends) {
      PlannedRun r;
      r.scenario = &scenario;
      r.backend = &b;
      runs.push_back(r);
    }
    const auto result = [](double error, double wall, Verdict v) {
      RunResult r;
      r.record.state = "completed";
      r.record.wall_time_s = wall;
      MetricResult x;
      x.value = 1.0 + error;
      x.reference = 1.0;
      x.reference_label = "exact (eq. 1, \"a\")";
      x.error = error;
      x.tolerance = 0.05;
      x.verdict = v;
      r.metrics.push_back(x);
      return r;
    };
    results = {result(0.01, 30.0, Verdict::pass), result(0.2, 3.0, Verdict::fail)};
    results[0].run = &runs[0];
    results[1].run = &runs[1];
    results[0].iterations_per_window = 4.5;  // implicit
    results[1].iterations_per_window = 1.0;  // explicit
  }
};

TEST(Report, OneCsvRowPerRunAndMetric) {
  ScratchDirectory dir;
  TwoBackends b;
  write_results_csv(dir.path() / "results.csv", b.results);
  const CsvTable t = CsvTable::read(dir.path() / "results.csv");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.text(0, t.index("backend")), "ice");
  EXPECT_EQ(t.text(1, t.index("verdict")), "fail");
  EXPECT_DOUBLE_EQ(t.row(0)[t.index("error")], 0.01);
  EXPECT_DOUBLE_EQ(t.row(1)[t.index("wall_time_s")], 3.0);
  EXPECT_EQ(t.text(0, t.index("reference_label")), "exact (eq. 1, \"a\")");  // quoted in the file
  EXPECT_DOUBLE_EQ(t.row(0)[t.index("iterations_per_window")], 4.5);
  EXPECT_DOUBLE_EQ(t.row(1)[t.index("iterations_per_window")], 1.0);
}

TEST(Report, SaysWhichPairingWasClosestAndWhichCheapest) {
  TwoBackends b;
  const std::string s = scenario_summary(b.suite.scenarios[0], {&b.results[0], &b.results[1]});
  EXPECT_NE(s.find("Closest to the reference: **ice**"), std::string::npos) << s;
  EXPECT_NE(s.find("Cheapest: **openfoam**"), std::string::npos) << s;
  EXPECT_NE(s.find("openfoam is outside tolerance on 1 metric"), std::string::npos) << s;
}

TEST(Report, TheMarkdownTableKeepsItsColumns) {
  ScratchDirectory dir;
  TwoBackends b;
  write_report(dir.path() / "report.md", b.suite, b.results,
               {"test machine", "now", Resolution::coarse, false, "none"});
  std::ifstream in(dir.path() / "report.md");
  std::string line, row;
  while (std::getline(in, line))
    if (line.rfind("| speed", 0) == 0) row = line;
  ASSERT_FALSE(row.empty());
  EXPECT_NE(row.find("speed \\|u\\|"), std::string::npos) << row;  // the label's bars escaped
  EXPECT_EQ(std::count(row.begin(), row.end(), '|') - std::count(row.begin(), row.end(), '\\'), 5)
      << row;
  std::ifstream again(dir.path() / "report.md");
  std::string iterations;
  while (std::getline(again, line))
    if (line.rfind("| iterations per window", 0) == 0) iterations = line;
  EXPECT_EQ(iterations, "| iterations per window (median) | | 4.5 | 1 |");
}

TEST(Report, NamesTheBackendsThatCannotRunAScenarioAndWhy) {
  ScratchDirectory dir;
  TwoBackends b;
  b.suite.scenarios[0].not_represented.push_back(
      {&backend("swe"), "no pores in a depth-averaged fluid", {}});
  write_report(dir.path() / "report.md", b.suite, b.results,
               {"test machine", "now", Resolution::coarse, false, "none"});
  std::ifstream in(dir.path() / "report.md");
  std::string line, found;
  while (std::getline(in, line))
    if (line.find("not represented") != std::string::npos) found = line;
  EXPECT_EQ(found, "- **swe** not represented: no pores in a depth-averaged fluid");
}

}  // namespace
}  // namespace cosim::bench

// swe_fluid repeating windows. Standalone with --cosim-repeat-windows: every
// window of a shipped case runs twice, going back to the state saved at its
// start once, and the run must leave exactly the files of a plain run with
// the same windows; prints what saving and restoring the state cost per
// window against the solver's own time in the window. In an implicit job: its
// files hold the accepted attempt of every window and nothing else.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hdf5_contents.hpp"
#include "hdf5_reader.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using ::testing::IsEmpty;
namespace fs = std::filesystem;

struct WindowedCase {
  const char* name;
  const char* file;  // under configs/swe
  const char* time;  // the case's `time` line
  double end_time, window;
};

void PrintTo(const WindowedCase& c, std::ostream* os) {
  *os << c.name;
}

std::set<std::string> file_names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

// "" when the texts are equal, else their first differing line.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream in_a(a), in_b(b);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(in_a, line_a));
    const bool more_b = static_cast<bool>(std::getline(in_b, line_b));
    if (!more_a && !more_b) return {};
    if (more_a != more_b || line_a != line_b)
      return fmt::format("line {}: '{}' / '{}'", line, more_a ? line_a : "(end)",
                         more_b ? line_b : "(end)");
  }
}

// The datasets and attributes that differ between two HDF5 files' contents.
std::vector<std::string> differing_entries(const std::map<std::string, std::string>& a,
                                           const std::map<std::string, std::string>& b) {
  std::vector<std::string> entries;
  for (const auto& [path, value] : a)
    if (!b.contains(path) || b.at(path) != value) entries.push_back(path);
  for (const auto& [path, value] : b)
    if (!a.contains(path)) entries.push_back(path);
  return entries;
}

nlohmann::json summary_of(const fs::path& run) {
  return nlohmann::json::parse(read_text(run / "summary.json"));
}

class SweRepeatWindows : public ::testing::TestWithParam<WindowedCase> {};

TEST_P(SweRepeatWindows, RepeatedWindowsWriteWhatAPlainRunWrites) {
  const WindowedCase& c = GetParam();
  const fs::path dir = fresh_directory(std::string("swe_repeat_windows_") + c.name);
  const std::string text = read_text(fs::path(COSIM_SOURCE_DIR) / "configs" / "swe" / c.file);
  write_text(dir / "case.yaml",
             replaced(text, c.time,
                      fmt::format("time: {{end_time: {}, window: {}}}", c.end_time, c.window)));
  for (const char* name : {"plain", "repeated"}) {
    std::vector<std::string> args{binary("swe_fluid").string(),
                                  "--config",
                                  (dir / "case.yaml").string(),
                                  "--output",
                                  (dir / name).string(),
                                  "--threads",
                                  "1",
                                  "--verbosity",
                                  "quiet"};
    if (std::string(name) == "repeated") args.push_back("--cosim-repeat-windows");
    const ProcessResult r = run(args, std::chrono::seconds(300));
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.output;
  }
  const fs::path plain = dir / "plain", repeated = dir / "repeated";

  const std::set<std::string> files = file_names(plain);
  ASSERT_EQ(files, file_names(repeated));
  std::size_t snapshots_inside_windows = 0;
  for (const std::string& file : files) {
    if (file == "log.txt" || file == "summary.json") continue;  // wall times
    if (fs::path(file).extension() != ".h5") {
      EXPECT_EQ(first_difference(read_text(plain / file), read_text(repeated / file)), "") << file;
      continue;
    }
    const auto contents = hdf5_contents(plain / file);
    if (file != "swe_mesh.h5") {
      ASSERT_TRUE(contents.contains("/fields/h")) << file;
    }
    EXPECT_THAT(differing_entries(contents, hdf5_contents(repeated / file)), IsEmpty()) << file;
  }
  for (const auto& row : read_csv(plain / "water.csv")) {
    const double windows = row[0] / c.window;
    if (std::abs(windows - std::round(windows)) > 1e-6) ++snapshots_inside_windows;
  }
  EXPECT_GT(snapshots_inside_windows, 0u) << "no snapshot was held inside a window";
  const std::size_t windows = static_cast<std::size_t>(std::ceil(c.end_time / c.window - 1e-9));
  EXPECT_GT(read_csv(plain / "gauges.csv").size(), windows);

  const nlohmann::json p = summary_of(plain), r = summary_of(repeated);
  EXPECT_EQ(r["status"]["exit_code"], 0);
  for (const char* key : {"steps", "windows", "conserved", "metrics"}) EXPECT_EQ(p[key], r[key]);
  const nlohmann::json& phases = r["wall_time_s"]["phases"];
  EXPECT_FALSE(p["wall_time_s"]["phases"].contains("save_state")) << "a plain run saves nothing";
  ASSERT_TRUE(phases.contains("restore_state")) << "the windows were not repeated";

  // Per window: one save (the first also allocates the copy), one restore,
  // and two attempts of the solver's steps.
  const auto per_window = [&](const char* phase) {
    return phases[phase].get<double>() / static_cast<double>(windows);
  };
  const double save = per_window("save_state"), restore = per_window("restore_state");
  const double attempt = per_window("advance") / 2.0;
  fmt::print(
      "{}: {} cells, {} windows of {} s, {:.3g} steps each: per window save {:.3g} ms + restore "
      "{:.3g} ms = {:.2g} % of one attempt's solver time ({:.3g} ms)\n",
      c.name, p["case"]["cells"].get<int>(), windows, c.window,
      p["steps"].get<double>() / static_cast<double>(windows), 1e3 * save, 1e3 * restore,
      100.0 * (save + restore) / attempt, 1e3 * attempt);
}

INSTANTIATE_TEST_SUITE_P(ShippedCases, SweRepeatWindows,
                         ::testing::Values(
                             // Snapshots every 0.25 s, inside windows; gauge rows every step.
                             WindowedCase{"dry_dam_break_1d", "dry_dam_break.yaml",
                                          "time: {end_time: 1.5}", 1.5, 0.1},
                             // Snapshots every 0.1 s, inside windows; gauge rows every step.
                             WindowedCase{"radial_dam_break_2d", "radial_dam_break_2d.yaml",
                                          "time: {end_time: 0.4}", 0.4, 0.03}),
                         [](const auto& p) { return std::string(p.param.name); });

// A dam break on a bed the soil (a test participant) raises at 0.1 m/s and
// reads the traction of: with the parallel-implicit scheme every window runs
// twice (the first iterate is the bed of the window's start, the second the
// bed of its end, the answer). Snapshots fall inside windows, gauge rows come
// every step: only the accepted attempt may show.
TEST(SweImplicitJob, WritesTheAcceptedAttemptOfEveryWindowOnly) {
  const fs::path dir = fresh_directory("swe_repeat_windows_implicit");
  write_text(dir / "job.yaml", R"(kind: job
name: swe_implicit
end_time: 0.2
window: 0.02
participants:
  soil:
    executable: cosim_test_participant
    config: soil.yaml
    meshes: {grid: {kind: uniform_grid, dim: 1}}
    writes: {bed_elevation: grid}
    reads: {bed_traction: grid}
  water:
    executable: swe_fluid
    config: water.yaml
    meshes: {swe_cells: {kind: nonuniform_line, dim: 1}}
    writes: {bed_traction: swe_cells}
    reads: {bed_elevation: swe_cells}
exchange:
  - {from: soil, to: water, field: bed_elevation, mapping: consistent}
  - {from: water, to: soil, field: bed_traction, mapping: consistent}
coupling:
  scheme: parallel-implicit
  convergence: [{field: water.bed_elevation, absolute: 1.0e-12}]
)");
  write_text(dir / "soil.yaml", R"(kind: test_participant
dt: 0.01
mesh: {dim: 1, origin: [0.0], spacing: [0.1], cells: [40]}
writes:
  - {name: bed_elevation, unit: m, function: [0, 0, 0, 0, 0.1]}
reads:
  - {name: bed_traction, unit: Pa, components: 2}
)");
  write_text(dir / "water.yaml", R"(kind: swe_case
name: water
dimension: 1
mesh: {from: 0.0, to: 4.0, cells: 80}
initial:
  depth: 0.0
  regions:
    - {box: {min: [0.0], max: [1.0]}, depth: 0.5}
boundaries: {left: wall, right: wall}
time: {end_time: 0.2}
output:
  every: 0.05
  gauges:
    - {name: middle, x: 2.0}
)");
  const ProcessResult r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(),
                               "--output", (dir / "run").string()},
                              std::chrono::seconds(120));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path water = dir / "run" / "water";

  const auto iterations = read_csv(dir / "run" / "coupling_iterations.csv");
  ASSERT_EQ(iterations.size(), 10u);
  for (const auto& row : iterations) {
    EXPECT_GE(row[2], 2.0) << "window " << row[0] << " was not repeated";
    EXPECT_EQ(row[3], 1.0) << "window " << row[0] << " did not converge";
  }
  // A row per accepted step, times increasing: none of a dropped attempt.
  const auto gauges = read_csv(water / "gauges.csv");
  const auto summary = nlohmann::json::parse(read_text(water / "summary.json"));
  EXPECT_EQ(gauges.size(), summary["steps"].get<std::size_t>() + 1);
  for (std::size_t k = 1; k < gauges.size(); ++k) ASSERT_GT(gauges[k][0], gauges[k - 1][0]);
  EXPECT_NEAR(gauges.back()[0], 0.2, 1e-12);
  EXPECT_EQ(read_csv(water / "water.csv").size(), 5u);  // t = 0, 0.05, ..., 0.2
  EXPECT_FALSE(fs::exists(water / "swe_000005.h5"));

  // Each snapshot shows the accepted attempt's bed, the answer at the end of
  // the window it falls in (0.06 s, 0.1 s, 0.16 s, 0.2 s); the first attempt
  // read the bed of the window's start.
  const std::pair<const char*, double> snapshots[] = {{"swe_000001.h5", 0.006},
                                                      {"swe_000002.h5", 0.01},
                                                      {"swe_000003.h5", 0.016},
                                                      {"swe_000004.h5", 0.02}};
  for (const auto& [file, bed] : snapshots)
    for (const double value : Hdf5Reader(water / file).doubles("/fields/bed").values)
      ASSERT_NEAR(value, bed, 1e-12) << file;
}

}  // namespace
}  // namespace cosim::testing

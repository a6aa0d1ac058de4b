// swe_fluid standalone with --cosim-repeat-windows: every window of a shipped
// case runs twice, going back to the state saved at its start once, and the
// run must leave exactly the files of a plain run with the same windows.
// Prints what saving and restoring the state cost per window against the
// solver's own time in the window.

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

}  // namespace
}  // namespace cosim::testing

// End to end: `mpm_solver --cosim-repeat-windows` runs every window of a
// standalone case twice, going back to the window's start once, and writes
// exactly what the same run without it writes: every HDF5 dataset and
// attribute bit for bit, the XDMF indexes and probes.csv as text, the same
// totals and counts in summary.json.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "hdf5_contents.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

// A cohesive sand column (Mohr-Coulomb with softening and cohesion
// degradation) collapsing under its weight and a ramped pressure, a boulder
// (free rigid body) falling on it, a fixed floor, the column cooled through
// x_min: 492 particles (324 of sand), 0.1 s in windows of 0.01 s. Snapshots
// (0.025 s) and probes (0.004 s) fall inside windows as well as at their ends.
const char* const collapsing_column = R"(kind: mpm_case
name: collapsing_column
dimension: 2
grid: {origin: [0, 0], upper: [1, 0.5], cells: [20, 10]}
time: {end_time: 0.1, safety_factor: 0.4, window: 0.01}
gravity: [0, -9.81]
materials:
  sand:
    type: mohr_coulomb
    density: 2000
    youngs_modulus: 2.0e6
    poisson_ratio: 0.3
    friction_angle: 35
    residual_friction_angle: 25
    softening_rate: 10
    dilatancy: rowe
    cohesion: 500
    tensile_strength: 200
    cohesion_degradation: {critical_volumetric_strain: 0.005}
    specific_heat: 800
    thermal_conductivity: 50
bodies:
  - name: column
    material: sand
    geometry: {box: {min: [0, 0.1], max: [0.3, 0.4]}}
    particles_per_cell: 3
    temperature: 350
  - name: floor
    rigid: {motion: fixed}
    density: 2000
    geometry: {box: {min: [0, 0], max: [1, 0.1]}}
  - name: boulder
    rigid: {motion: free}
    density: 3000
    geometry: {box: {min: [0.1, 0.42], max: [0.2, 0.47]}}
contact: {enabled: true, friction: 0.3}
boundaries: {x_min: slip, x_max: slip, y_min: fixed, y_max: free}
thermal: {x_min: {type: fixed_temperature, temperature: 300}}
loads:
  - {name: push, body: column, region: {min: [0, 0.38], max: [0.1, 0.4]}, pressure: 2000,
     ramp_time: 0.01}
probes:
  - {name: toe, body: column, position: [0.28, 0.12]}
  - {name: crest, body: column, position: [0.02, 0.38]}
output: {every: 0.025, grid: true, probe_every: 0.004}
threads: 1
)";

nlohmann::json run_solver(const fs::path& dir, const std::string& name, bool repeat) {
  std::vector<std::string> args{binary("mpm_solver").string(), "--config",
                                (dir / "case.yaml").string(), "--output", (dir / name).string()};
  if (repeat) args.push_back("--cosim-repeat-windows");
  const auto result = run(args, std::chrono::seconds(120));
  EXPECT_EQ(result.exit_code, 0) << name << "\n" << result.output;
  return nlohmann::json::parse(read_text(dir / name / "summary.json"));
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

// Every dataset and attribute of two HDF5 files, byte for byte.
void expect_same_datasets(const fs::path& a, const fs::path& b) {
  const auto x = hdf5_contents(a);
  const auto y = hdf5_contents(b);
  EXPECT_TRUE(x.contains("/fields/velocity") || x.contains("/fields/mass")) << a.filename();
  EXPECT_EQ(x.size(), y.size()) << a.filename();
  for (const auto& [path, bytes] : x) {
    const auto other = y.find(path);
    EXPECT_TRUE(other != y.end() && other->second == bytes)
        << a.filename() << " " << path << " differs";
  }
}

// Compares every output file of the runs in <dir>/plain and <dir>/repeated
// but log.txt and summary.json (wall times); returns how many it compared.
int expect_same_outputs(const fs::path& dir) {
  const auto files = files_in(dir / "plain");
  EXPECT_EQ(files, files_in(dir / "repeated"));
  int compared = 0;
  for (const std::string& file : files) {
    const fs::path a = dir / "plain" / file;
    const fs::path b = dir / "repeated" / file;
    if (!fs::exists(b)) continue;
    const std::string extension = fs::path(file).extension();
    if (extension == ".h5") {
      expect_same_datasets(a, b);
    } else if (extension == ".xdmf" || extension == ".csv") {
      EXPECT_TRUE(read_text(a) == read_text(b)) << file << " differs";
    } else {
      continue;
    }
    ++compared;
  }
  return compared;
}

TEST(MpmRepeatedWindows, WriteExactlyWhatAPlainRunWrites) {
  const fs::path dir = fresh_directory("mpm_repeat_windows");
  write_text(dir / "case.yaml", collapsing_column);
  const nlohmann::json plain = run_solver(dir, "plain", false);
  const nlohmann::json repeated = run_solver(dir, "repeated", true);

  // particles and grid: 5 snapshots each (0, 0.025, ..., 0.1) and their
  // indexes; probes.csv with a row every 0.004 s.
  EXPECT_EQ(expect_same_outputs(dir), 2 * 5 + 2 + 1);
  EXPECT_EQ(read_csv(dir / "plain" / "probes.csv").size(), 26u);

  EXPECT_EQ(plain["steps"], repeated["steps"]);
  EXPECT_EQ(plain["conserved"], repeated["conserved"]);
  for (const char* metric :
       {"simulated_time", "snapshots", "stable_time_step_min", "stable_time_step_max"})
    EXPECT_EQ(plain["metrics"][metric], repeated["metrics"][metric]) << metric;
  // The material state changed: the check covers it.
  const double plastic_work = plain["conserved"]["plastic_dissipation"]["end"];
  EXPECT_GT(plastic_work, 0.0);

  // Ten windows, each saved once and run twice.
  EXPECT_EQ(plain["coupling"]["windows"], 10);
  EXPECT_EQ(plain["coupling"]["iterations"], 10);
  EXPECT_FALSE(plain["metrics"].contains("state_saves"));
  EXPECT_EQ(repeated["coupling"]["windows"], 10);
  EXPECT_EQ(repeated["coupling"]["iterations"], 20);
  EXPECT_EQ(repeated["metrics"]["state_saves"]["value"], 10);
  EXPECT_EQ(repeated["metrics"]["state_restores"]["value"], 10);
  const double save_restore = repeated["metrics"]["save_restore_seconds"]["value"];
  const double advance = repeated["wall_time_s"]["phases"]["advance"];
  std::printf(
      "%g particles: save + restore %.3g ms per window, %.2f %% of a window's solver time "
      "(%.3g ms)\n",
      plain["metrics"]["particles"]["value"].get<double>(), 1e3 * save_restore / 10,
      100.0 * save_restore / (advance / 2.0), 1e3 * advance / 20);
}

// Without a window the whole run is one window: run twice, it still writes
// what a plain run writes.
TEST(MpmRepeatedWindows, OneWindowWithoutTimeWindow) {
  const fs::path dir = fresh_directory("mpm_repeat_one_window");
  std::string text = collapsing_column;
  text.replace(text.find(", window: 0.01"), std::string(", window: 0.01").size(), "");
  text.replace(text.find("end_time: 0.1"), std::string("end_time: 0.1").size(), "end_time: 0.03");
  write_text(dir / "case.yaml", text);
  const nlohmann::json plain = run_solver(dir, "plain", false);
  const nlohmann::json repeated = run_solver(dir, "repeated", true);
  EXPECT_FALSE(plain.contains("coupling"));  // no window, no participant
  EXPECT_EQ(repeated["coupling"]["iterations"], 2);
  EXPECT_EQ(plain["steps"], repeated["steps"]);
  EXPECT_EQ(plain["conserved"], repeated["conserved"]);
  // Snapshots at 0, 0.025 and 0.03 s.
  EXPECT_EQ(expect_same_outputs(dir), 2 * 3 + 2 + 1);
}

}  // namespace
}  // namespace cosim::testing

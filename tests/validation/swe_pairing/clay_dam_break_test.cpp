// Zheng et al., Sec. 4.4: the clay column collapsing in a dam-break flow,
// R = h_l / h_r = 0.5, 1, 2, through `cosim run` to 10 s. The paper has no
// reference data ("we can only ... verify that the results are plausible"),
// so this checks what must hold: the job completes, the water volume is
// conserved to round-off while the bed moves under it, the waves reflect at
// the closed ends and decay so the surface returns towards rest, and the
// soil stops. Table 5's numbers are printed next to ours for information.
// CI runs the soil on the paper's 0.05 m GIMP grid
// (configs/mpm/clay_column_variants/paper_gimp_0.05m.yaml, a quarter of the
// points, half the steps); COSIM_FULL_VALIDATION runs the jobs as shipped
// (quadratic B-splines on 0.025 m cells).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace fs = std::filesystem;
namespace ct = cosim::testing;

namespace {

constexpr double g = 9.81;

struct Table5Row {
  double runout, eta_max, soil_speed, water_speed;
};

// Zheng et al., Table 5 (R, t) -> Ds/h_s, eta_max/h_s, |v_s|max, |u_0|max.
const std::map<std::pair<std::string, double>, Table5Row> table5 = {
    {{"0.5", 0.5}, {0.633, 1.461, 0.651, 0.405}}, {{"0.5", 1.0}, {1.240, 1.297, 0.432, 0.616}},
    {{"0.5", 5.0}, {1.230, 1.371, 0.089, 0.032}}, {{"1", 0.5}, {0.589, 1.943, 0.618, 1.064}},
    {{"1", 1.0}, {1.186, 1.458, 0.413, 0.762}},   {{"1", 5.0}, {1.229, 1.572, 0.085, 0.215}},
    {{"2", 0.5}, {0.560, 2.581, 0.569, 1.816}},   {{"2", 1.0}, {1.015, 1.710, 0.386, 1.316}},
    {{"2", 5.0}, {1.032, 1.606, 0.080, 0.398}},
};

// The job file to run: the shipped one, or at CI resolution a copy in `dir`
// whose soil is the paper's 0.05 m GIMP case.
fs::path job_file(const std::string& tag, [[maybe_unused]] const fs::path& dir) {
  const fs::path configs = fs::path(COSIM_SOURCE_DIR) / "configs";
  const fs::path shipped = configs / ("clay_dam_break_R" + tag + ".yaml");
#ifdef COSIM_FULL_VALIDATION
  return shipped;
#else
  std::string text = ct::read_text(shipped);
  text = ct::replaced(
      text, "config: mpm/clay_column_seed002.yaml",
      "config: " + (configs / "mpm" / "clay_column_variants" / "paper_gimp_0.05m.yaml").string());
  text = ct::replaced(text, "config: swe/", "config: " + (configs / "swe").string() + "/");
  const fs::path job = dir / ("clay_dam_break_R" + tag + "_ci.yaml");
  std::ofstream(job) << text;
  return job;
#endif
}

class ClayColumnInDamBreak : public ::testing::TestWithParam<const char*> {};

TEST_P(ClayColumnInDamBreak, RunsTenSecondsAndTheWaterReturnsTowardsRest) {
  const std::string tag = GetParam();
  const fs::path out = ct::fresh_directory("clay_dam_break_R" + tag);
  const fs::path job = job_file(tag, ct::fresh_directory("clay_dam_break_R" + tag + "_job"));
  const auto result = ct::run({ct::binary("cosim").string(), "run", job.string(), "--output",
                               out.string(), "--verbosity", "quiet"},
                              std::chrono::seconds(1200));
  ASSERT_EQ(result.exit_code, 0) << result.output;

  const auto water = nlohmann::json::parse(ct::read_text(out / "water" / "summary.json"));
  const double volume_change = water["conserved"]["water_volume"]["relative_change"].get<double>();
  fmt::print("R = {}: water volume relative change {:.2e} (tolerance 1e-12)\n", tag, volume_change);
  EXPECT_LT(std::abs(volume_change), 1e-12);

  // water.csv rows: time, volume, eta_max, eta_min, speed_max (every 0.1 s).
  const auto rows = ct::read_csv(out / "water" / "water.csv");
  ASSERT_FALSE(rows.empty());
  EXPECT_NEAR(rows.back()[0], 10.0, 1e-6);
  auto range_over = [&](double from, double to) {
    double r = 0.0;
    for (const auto& row : rows)
      if (row[0] >= from - 1e-9 && row[0] <= to + 1e-9) r = std::max(r, row[2] - row[3]);
    return r;
  };
  const double early = range_over(0.0, 2.0), late = range_over(9.0, 10.0);
  fmt::print(
      "R = {}: free-surface range max(eta) - min(eta): {:.3f} m over 0-2 s, {:.3f} m over 9-10 s\n",
      tag, early, late);
  EXPECT_LT(late, 0.6 * early) << "the surface does not settle";

  // Waves reach the far wall: the right-end gauge rises above the still level.
  double right_end_peak = 0.0;
  for (const auto& row : ct::read_csv(out / "water" / "gauges.csv"))
    right_end_peak = std::max(right_end_peak, row[4]);
  fmt::print("R = {}: highest free surface at the right wall {:.3f} m (still level 1 m)\n", tag,
             right_end_peak);
  EXPECT_GT(right_end_peak, 1.01);

  std::map<double, std::vector<double>> water_at;
  for (const auto& row : rows) water_at[std::round(row[0] * 1e6) / 1e6] = row;
  fmt::print("R = {}: t [s]  eta_max/h_s ours (paper)   |u_0|max ours (paper)\n", tag);
  for (double t : {0.5, 1.0, 5.0}) {
    const Table5Row ref = table5.at({tag, t});
    const auto& row = water_at.at(t);
    fmt::print("        {:4.1f}   {:.3f} ({:.3f})            {:.3f} ({:.3f})\n", t, row[2],
               ref.eta_max, row[4] / std::sqrt(g), ref.water_speed);
  }
  const auto soil = nlohmann::json::parse(ct::read_text(out / "soil" / "summary.json"));
  EXPECT_EQ(soil["status"]["exit_code"], 0);
}

INSTANTIATE_TEST_SUITE_P(ZhengSec44, ClayColumnInDamBreak, ::testing::Values("0.5", "1", "2"),
                         [](const auto& p) {
                           std::string name = std::string("R") + p.param;
                           std::replace(name.begin(), name.end(), '.', '_');
                           return name;
                         });

}  // namespace

// The earthquake-induced submarine landslide of Tran et al., MPMICE
// ("Earthquake-induced submarine landslides", Figs. 18-23), run end to end by
// cosim on the MPM <-> ICE pairing: a 20 m, 45 deg slope of undrained,
// dilatant, softening soil under 20 m of sea on a shaking table's plate
// (1 g at 2 Hz) (configs/ice_coupled/submarine_landslide/job.yaml: 2 m
// cells, 5 s with the shaking from 0.5 s; with -DCOSIM_FULL_VALIDATION=ON
// full/job.yaml: 0.25 m cells, 30 s with the shaking from 3 to 23 s). The
// paper gives figures only: the checks are qualitative, each printed with
// its number:
//  - the slope fails: over the shaking the toe moves out by more than 0.1 m
//    and the crest settles (by more than 1 cm);
//  - the shear strain localises: the 5 % most sheared points have more than
//    five times the median's accumulated plastic strain (at 2 m cells the
//    yielding gathers in the crest's top layer and along the face, the skin
//    of a cohesionless slope that the table shakes through its friction;
//    inside the slope it is diffuse, its 90th percentile ~1.7 times the
//    median);
//  - the pore water pressure falls below hydrostatic where the soil shears
//    (the paper's observation 2: the soil dilates, undrained): inside the
//    slope (more than 3 m below its initial surface, away from the skin,
//    whose cells a partly filled top row of the fluid's cells disturbs), the
//    cells of the 10 % most sheared points have a mean excess pore pressure
//    below -20 kPa and below that of the least sheared half;
//  - the water's mass is kept (relative change <= 1e-6), the momentum the
//    soil receives equals what the fluid gave it (<= 1e-12), exit code 0.
// Coarse wall time on the two shared CI cores: 20-36 s.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "run_process.hpp"
#include "scenario_snapshots.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

#ifdef COSIM_FULL_VALIDATION
constexpr const char* job = "configs/ice_coupled/submarine_landslide/full/job.yaml";
constexpr int timeout_s = 30 * 24 * 3600;
constexpr double shaking_start = 3.0, end_time = 30.0;
#else
constexpr const char* job = "configs/ice_coupled/submarine_landslide/job.yaml";
constexpr int timeout_s = 900;
constexpr double shaking_start = 0.5, end_time = 5.0;
#endif

// The fluid's grid (water.yaml): x = 0 ... 120 m, y = 2 ... 50 m above the plate.
constexpr double x0 = 0.0, x1 = 120.0, y0 = 2.0, y1 = 50.0, sea_level = 42.0;

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

TEST(SubmarineLandslide, SlopeFailsWithLocalisedShearAndNegativeExcessPorePressure) {
  const fs::path dir = fresh_directory("submarine_landslide");
  const ProcessResult r =
      run({binary("cosim").string(), "run", (fs::path(COSIM_SOURCE_DIR) / job).string(), "--output",
           (dir / "run").string()},
          std::chrono::seconds(timeout_s));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  // probes.csv: time, then per probe (crest, toe, face) its displacement, velocity, ...
  const auto probes = read_csv(dir / "run" / "soil" / "probes.csv");
  ASSERT_GT(probes.size(), 10u);
  const std::string text = read_text(dir / "run" / "soil" / "probes.csv");
  const auto column = [&](const std::string& name) {
    std::size_t index = 0, from = 0;
    const std::string header = text.substr(0, text.find('\n'));
    while (from <= header.size()) {
      const std::size_t to = std::min(header.find(',', from), header.size());
      if (header.substr(from, to - from).rfind(name, 0) == 0) return index;
      ++index;
      from = to + 1;
    }
    ADD_FAILURE() << "no column " << name << " in probes.csv";
    return std::size_t{0};
  };
  const std::size_t crest_y = column("crest_displacement_y"), toe_x = column("toe_displacement_x");
  const auto row_at = [&](double t) {
    return *std::min_element(probes.begin(), probes.end(), [&](auto& a, auto& b) {
      return std::abs(a[0] - t) < std::abs(b[0] - t);
    });
  };
  const auto start = row_at(shaking_start), end = row_at(end_time);
  const double toe_out = end[toe_x] - start[toe_x];
  const double settlement = -end[crest_y];
  fmt::print(
      "over the shaking ({} to {} s): the toe moves out {:.3f} m (> 0.1 m); the crest has settled "
      "{:.3f} m (> 0.01 m)\n",
      start[0], end[0], toe_out, settlement);
  EXPECT_GT(toe_out, 0.1);
  EXPECT_GT(settlement, 0.01);

  const auto particles = particle_snapshots(dir / "run" / "soil");
  const auto cells = cell_snapshots(dir / "run" / "water");
  const double last = particles.rbegin()->first;
  ASSERT_NEAR(last, end_time, 1e-6);
  ASSERT_TRUE(cells.count(last));
  const ParticleSnapshot& s = particles.at(last);
  const CellSnapshot& c = cells.at(last);
  std::vector<double> strain;
  for (std::size_t p = 0; p < s.x.size(); ++p)
    if (s.body[p] == 0) strain.push_back(s.plastic_strain[p]);
  const double sheared = percentile(strain, 0.95), median = percentile(strain, 0.5);
  fmt::print(
      "plastic shear strain at {} s: 95th percentile {:.4f}, median {:.4f} (ratio {:.1f}, > 5), "
      "largest {:.3f}\n",
      last, sheared, median, sheared / median, *std::max_element(strain.begin(), strain.end()));
  EXPECT_GT(sheared, 5.0 * median);

  const double dx = (x1 - x0) / c.nx, dy = (y1 - y0) / c.ny;
  const auto excess = [&](double x, double y) {
    const int i = std::clamp(static_cast<int>((x - x0) / dx), 0, c.nx - 1);
    const int j = std::clamp(static_cast<int>((y - y0) / dy), 0, c.ny - 1);
    const double centre = y0 + (j + 0.5) * dy;
    return c.at(c.pressure, i, j) - (101325.0 + 999.8 * 9.81 * std::max(sea_level - centre, 0.0));
  };
  // Depth below the slope's initial surface (the crest at y = 22 m, the face x + y = 54 m).
  const auto depth = [](double x, double y) {
    return std::min(22.0 - y, (54.0 - x - y) / std::sqrt(2.0));
  };
  std::vector<double> inner;
  for (std::size_t p = 0; p < s.x.size(); ++p)
    if (s.body[p] == 0 && depth(s.x0[p], s.y0[p]) > 3.0 && s.y[p] > y0 + dy)
      inner.push_back(s.plastic_strain[p]);
  ASSERT_GT(inner.size(), 100u);
  const double inner_sheared = percentile(inner, 0.9), inner_median = percentile(inner, 0.5);
  double sheared_sum = 0.0, rest_sum = 0.0, lowest = 1e300;
  int sheared_count = 0, rest_count = 0;
  for (std::size_t p = 0; p < s.x.size(); ++p) {
    if (s.body[p] != 0 || s.y[p] < y0) continue;
    const double e = excess(s.x[p], s.y[p]);
    lowest = std::min(lowest, e);
    if (!(depth(s.x0[p], s.y0[p]) > 3.0 && s.y[p] > y0 + dy)) continue;
    if (s.plastic_strain[p] >= inner_sheared) {
      sheared_sum += e;
      ++sheared_count;
    } else if (s.plastic_strain[p] < inner_median) {
      rest_sum += e;
      ++rest_count;
    }
  }
  ASSERT_GT(sheared_count, 0);
  ASSERT_GT(rest_count, 0);
  const double sheared_excess = sheared_sum / sheared_count, rest_excess = rest_sum / rest_count;
  fmt::print(
      "inside the slope at {} s: plastic strain 90th percentile {:.4f}, median {:.4f}; excess pore "
      "pressure in the cells of the 10 % most sheared points {:+.1f} kPa (< -20 kPa), of the least "
      "sheared half {:+.1f} kPa; lowest in the soil {:+.1f} kPa\n",
      last, inner_sheared, inner_median, sheared_excess / 1e3, rest_excess / 1e3, lowest / 1e3);
  EXPECT_LT(sheared_excess, -20e3);
  EXPECT_LT(sheared_excess, rest_excess);

  const auto water = nlohmann::json::parse(read_text(dir / "run" / "water" / "summary.json"));
  const double mass = water["conserved"]["mass_water"]["relative_change"].get<double>();
  const auto coupler = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  const double balance =
      coupler["metrics"]["max_momentum_exchange_balance_error"]["value"].get<double>();
  fmt::print("water mass change {:.1e} (tolerance 1e-6); momentum balance {:.1e} (1e-12)\n", mass,
             balance);
  EXPECT_LE(std::abs(mass), 1e-6);
  EXPECT_LE(balance, 1e-12);
}

}  // namespace
}  // namespace cosim::testing

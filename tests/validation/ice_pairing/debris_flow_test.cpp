// The underwater debris flow of Tran et al., MPMICE ("Underwater debris
// flow", Table 1; Rzadkiewicz et al.'s experiment), run end to end by cosim
// on the MPM <-> ICE pairing: a triangle of saturated sand released on a
// rigid 45 deg bed under 1.6 m of water, air above
// (configs/ice_coupled/debris_underwater/job.yaml: 70 x 40 cells of 5 cm,
// 0.8 s; with -DCOSIM_FULL_VALIDATION=ON full/job.yaml, the paper's 700 x
// 400 cells). The paper's Figs. 12-13 are not available as numbers: the
// checks are qualitative (BENCHMARKS.md, debris-underwater), each printed
// with its number:
//  - the slide's front runs down the bed: it has left the box's toe by
//    0.8 s, further than at 0.4 s, and by no more than a frictionless
//    Coulomb block of buoyant sand would in 0.8 s, g (1 - rho_w / rho_sat)
//    sin(45 deg) t^2 / 2 = 1.1 m;
//  - a trough forms in the free surface above the slide at 0.4 s and 0.8 s
//    (at least 2 cm deep) and a crest ahead of it (the wave runs off);
//  - the water's mass is kept (relative change <= 1e-6, its surface stays
//    well below the open top) and the momentum the sand receives equals what
//    the fluid gave it (<= 1e-12); the run ends with exit code 0 (NaN or a
//    failed step would be exit 4).
// Coarse wall time on the two shared CI cores: 72-100 s.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "scenario_snapshots.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

#ifdef COSIM_FULL_VALIDATION
constexpr const char* job = "configs/ice_coupled/debris_underwater/full/job.yaml";
constexpr int timeout_s = 30 * 24 * 3600;
#else
constexpr const char* job = "configs/ice_coupled/debris_underwater/job.yaml";
constexpr int timeout_s = 900;
#endif

constexpr double toe_x = 1.10, toe_y = 0.90;  // the sand's initial toe on the bed (sand.yaml)
constexpr double still_water = 1.6, domain_top = 2.0, domain_length = 3.5;

// How far the sand's farthest point has gone down the bed from the toe.
double front(const ParticleSnapshot& s) {
  double best = -1e300;
  for (std::size_t p = 0; p < s.x.size(); ++p) {
    if (s.body[p] != 0) continue;
    best = std::max(best, ((s.x[p] - toe_x) - (s.y[p] - toe_y)) / std::sqrt(2.0));
  }
  return best;
}

double front_x(const ParticleSnapshot& s) {
  double best = -1e300;
  for (std::size_t p = 0; p < s.x.size(); ++p)
    if (s.body[p] == 0) best = std::max(best, s.x[p]);
  return best;
}

// The free surface per column: the domain's top minus the air's share of each cell's fluid.
std::vector<double> free_surface(const CellSnapshot& c) {
  const double dy = domain_top / c.ny;
  std::vector<double> eta(static_cast<std::size_t>(c.nx), domain_top);
  for (int i = 0; i < c.nx; ++i)
    for (int j = 0; j < c.ny; ++j) {
      const double a = c.at(c.air, i, j), w = c.at(c.water, i, j);
      eta[static_cast<std::size_t>(i)] -= dy * a / std::max(a + w, 1e-300);
    }
  return eta;
}

TEST(DebrisFlowUnderwater, HydroplaningFrontAndTroughAboveTheSlide) {
  const fs::path dir = fresh_directory("debris_underwater");
  const ProcessResult r =
      run({binary("cosim").string(), "run", (fs::path(COSIM_SOURCE_DIR) / job).string(), "--output",
           (dir / "run").string()},
          std::chrono::seconds(timeout_s));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto particles = particle_snapshots(dir / "run" / "soil");
  const auto cells = cell_snapshots(dir / "run" / "water");
  for (double t : {0.0, 0.4, 0.8}) {
    ASSERT_TRUE(particles.count(t)) << "no particle snapshot at " << t << " s";
    ASSERT_TRUE(cells.count(t)) << "no ICE snapshot at " << t << " s";
  }
  const double coulomb = 9.81 * (1.0 - 999.8 / 1985.0) * std::sin(M_PI / 4.0) * 0.8 * 0.8 / 2.0;
  const double front_04 = front(particles.at(0.4)), front_08 = front(particles.at(0.8));
  fmt::print(
      "slide front down the bed from the toe: {:.3f} m at 0.4 s, {:.3f} m at 0.8 s (at 0.8 s > "
      "0.1 m, > at 0.4 s, <= {:.2f} m, a frictionless buoyant block)\n",
      front_04, front_08, coulomb);
  EXPECT_GT(front_08, 0.1);
  EXPECT_GT(front_08, front_04);
  EXPECT_LE(front_08, coulomb);

  for (double t : {0.4, 0.8}) {
    const CellSnapshot& c = cells.at(t);
    const std::vector<double> eta = free_surface(c);
    const double dx = domain_length / c.nx;
    const double sand_front = front_x(particles.at(t));
    double trough = 1e300, trough_x = 0.0, crest = -1e300, crest_x = 0.0, highest = -1e300;
    for (int i = 0; i < c.nx; ++i) {
      const double x = (i + 0.5) * dx;
      const double e = eta[static_cast<std::size_t>(i)] - still_water;
      if (x > 0.45 && x < sand_front && e < trough) trough = e, trough_x = x;
      if (x > sand_front && e > crest) crest = e, crest_x = x;
      if (x > 0.45) highest = std::max(highest, e);
    }
    fmt::print(
        "t = {} s: trough {:+.3f} m at x = {:.2f} m over the slide (tolerance <= -0.02 m), crest "
        "{:+.3f} m at x = {:.2f} m ahead of its front at x = {:.2f} m (> +0.005 m)\n",
        t, trough, trough_x, crest, crest_x, sand_front);
    EXPECT_LE(trough, -0.02);
    EXPECT_GT(crest, 0.005);
    EXPECT_LT(highest, domain_top - still_water - 0.1);  // the water stays in the tank
  }

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

// End to end: the MPM <-> ICE pairing (configs/ice_coupled/job.yaml): a
// saturated elastic soil column settling in still water, the drag solved by
// ice_fluid in its steps. The job completes; once the column has
// consolidated under its buoyant weight (c_v ~ 20 m^2/s: ~0.01 s) the pore
// pressure at the three gauges (in the soil's bottom and top cells and in
// the water above), averaged over the second half of the 0.1 s run, is
// hydrostatic within 0.5 % of the pressure at the bottom; the momentum the
// solid receives equals what the fluid gave it to 1e-12; the water's mass
// changes by less than 1e-8 (a little crosses the open top while the soil
// settles).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

TEST(IcePairing, SoilColumnInStillWaterConsolidatesToHydrostaticPorePressure) {
  const fs::path dir = fresh_directory("ice_pairing");
  const ProcessResult r =
      run({binary("cosim").string(), "run",
           (fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled/job.yaml").string(), "--output",
           (dir / "run").string()},
          std::chrono::seconds(300));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto gauges =
      read_csv(dir / "run" / "water" / "gauges.csv");  // time, then p, ux, uy, phi per gauge
  ASSERT_GT(gauges.size(), 10u);
  EXPECT_NEAR(gauges.back()[0], 0.1, 1e-9);
  const double heights[] = {0.0625, 0.4375, 0.8125};
  const double rho_g = 997.7 * 9.81;
  const double tolerance = 0.005 * rho_g * (1.0 - heights[0]);
  for (int g = 0; g < 3; ++g) {
    double sum = 0.0;
    int rows = 0;
    for (const auto& row : gauges) {
      if (row[0] < 0.05) continue;
      sum += row[static_cast<std::size_t>(1 + 4 * g)] - 101325.0;
      ++rows;
    }
    const double excess = sum / rows - rho_g * (1.0 - heights[g]);
    fmt::print("gauge at y = {}: mean excess pore pressure {:.1f} Pa (tolerance {:.1f} Pa)\n",
               heights[g], excess, tolerance);
    EXPECT_LE(std::abs(excess), tolerance);
  }
  const auto coupler = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  const double balance =
      coupler["metrics"]["max_momentum_exchange_balance_error"]["value"].get<double>();
  fmt::print("momentum the solid receives vs what the fluid gave: {:.1e} (tolerance 1e-12)\n",
             balance);
  EXPECT_LE(balance, 1e-12);
  const auto water = nlohmann::json::parse(read_text(dir / "run" / "water" / "summary.json"));
  EXPECT_LT(std::abs(water["conserved"]["mass_water"]["relative_change"].get<double>()), 1e-8);
}

}  // namespace
}  // namespace cosim::testing

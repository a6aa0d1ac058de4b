// End to end: the MPM <-> ICE pairing (configs/ice_coupled/job.yaml): a
// saturated elastic soil column in still water. The job completes, the
// pore pressure at the gauges, averaged over the second half of the run
// (the soil's settling sends pressure waves through the pores): above the
// soil within 3 % of hydrostatic; in the soil hydrostatic plus an excess
// between 0 and the buoyant weight of the soil above the gauge (the column
// consolidates under its own weight; undrained it would carry all of it);
// the water's mass is kept to 1e-6 (a little leaves and enters through the
// open top).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "run_process.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

TEST(IcePairing, SoilColumnInStillWaterKeepsHydrostaticPorePressure) {
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
  EXPECT_NEAR(gauges.back()[0], 0.02, 1e-9);
  const double heights[] = {0.0625, 0.4375, 0.8125};
  for (int g = 0; g < 3; ++g) {
    double sum = 0.0;
    int rows = 0;
    for (const auto& row : gauges) {
      if (row[0] < 0.01) continue;
      sum += row[static_cast<std::size_t>(1 + 4 * g)] - 101325.0;
      ++rows;
    }
    const double measured = sum / rows;
    const double hydrostatic = 997.7 * 9.81 * (1.0 - heights[g]);
    const double buoyant_soil = std::max(0.0, (2650.0 - 997.7) * 0.6 * 9.81 * (0.5 - heights[g]));
    fmt::print(
        "gauge at y = {}: mean pore pressure {:.0f} Pa; hydrostatic {:.0f} Pa, excess {:.0f} Pa "
        "(allowed -3 % of hydrostatic to {:.0f} Pa)\n",
        heights[g], measured, hydrostatic, measured - hydrostatic, buoyant_soil);
    EXPECT_GE(measured - hydrostatic, -0.03 * hydrostatic);
    EXPECT_LE(measured - hydrostatic, buoyant_soil + 0.03 * hydrostatic);
  }
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "water" / "summary.json"));
  EXPECT_LT(std::abs(summary["conserved"]["mass_water"]["relative_change"].get<double>()), 1e-6);
}

}  // namespace
}  // namespace cosim::testing

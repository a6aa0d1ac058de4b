// Darcy flow through a porous column on the MPM <-> ICE pairing
// (configs/ice_coupled/darcy, Tran et al., MPMICE, "Fluid flow through
// isothermal porous media"): water driven by dp through 1 m of grains held
// fixed (d = 1 mm) in a 2 m channel of 20 cells, the porous part 10 cells
// with one point each; ice_fluid solves the drag (Kozeny-Carman, eq. 29) in
// its steps. For the paper's five solid fractions and three pressure
// differences the steady pore-water velocity in the column is within 2 % of
//   U_f = (1/n) d^2 (1 - phi_s)^3 / (180 phi_s^2 mu) dp / L   (eq. 98),
// and the flux in the free water beside it is n U_f (mass is conserved).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bench/darcy_column.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using bench::DarcyColumn;

namespace fs = std::filesystem;

constexpr double grain_size = 1.0e-3;  // d [m]
constexpr double viscosity = 1.0e-3;   // mu [Pa s]
constexpr double atmosphere = 101325.0;
constexpr double length = 1.0;  // L [m]

struct Steady {
  double column_velocity = 0.0;  // ux at the column's centre [m/s]
  double inlet_velocity = 0.0;   // ux in the free water upstream [m/s]
  double drift = 0.0;            // |change| of the column velocity over the last 0.1 s, relative
};

Steady run_case(const fs::path& dir, double phi_s, double dp) {
  const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled/darcy";
  fs::create_directories(dir);
  write_text(dir / "job.yaml", read_text(source / "job.yaml"));
  write_text(dir / "column.yaml", replaced(read_text(source / "column.yaml"), "porosity: 0.4",
                                           fmt::format("porosity: {}", 1.0 - phi_s)));
  write_text(dir / "water.yaml", replaced(read_text(source / "water.yaml"), "pressure: 151987.5",
                                          fmt::format("pressure: {}", atmosphere + dp)));
  const ProcessResult r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(),
                               "--output", (dir / "run").string()},
                              std::chrono::seconds(300));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // time, then p, ux, uy, phi per gauge: column (x = 1 m), inlet (x = 0.25 m)
  const auto gauges = read_csv(dir / "run" / "water" / "gauges.csv");
  if (gauges.size() < 10) {
    ADD_FAILURE() << "no gauge rows";
    return {};
  }
  const auto& last = gauges.back();
  Steady s{last[2], last[6], 0.0};
  for (const auto& row : gauges) {
    if (row[0] >= last[0] - 0.1) {
      s.drift = std::abs(row[2] - last[2]) / std::abs(last[2]);
      break;
    }
  }
  return s;
}

TEST(DarcyPairing, PoreWaterVelocityMatchesEquation98ForAllFifteenCases) {
  const fs::path dir = fresh_directory("darcy_pairing");
  double worst = 0.0;
  for (double phi_s : {0.6, 0.62, 0.66, 0.68, 0.7}) {
    for (double atmospheres : {0.25, 0.5, 1.0}) {
      const double dp = atmospheres * atmosphere;
      const Steady s = run_case(dir / fmt::format("phi{}_dp{}", phi_s, atmospheres), phi_s, dp);
      const double exact = DarcyColumn{grain_size, viscosity, length}.pore_velocity(phi_s, dp);
      const double error = std::abs(s.column_velocity / exact - 1.0);
      const double flux_error = std::abs(s.inlet_velocity / ((1.0 - phi_s) * exact) - 1.0);
      worst = std::max(worst, error);
      fmt::print(
          "phi_s {:.2f}, dp {:.2f} atm: U_f {:.5f} m/s vs eq. 98 {:.5f} ({:+.3f} %, tolerance 2 "
          "%); "
          "free-water flux vs n U_f {:+.3f} %; drift over the last 0.1 s {:.1e}\n",
          phi_s, atmospheres, s.column_velocity, exact, 100.0 * (s.column_velocity / exact - 1.0),
          100.0 * (s.inlet_velocity / ((1.0 - phi_s) * exact) - 1.0), s.drift);
      EXPECT_LE(error, 0.02);
      EXPECT_LE(flux_error, 0.02);
      EXPECT_LE(s.drift, 1e-3);  // steady
    }
  }
  fmt::print("largest error over the 15 cases: {:.3f} % (tolerance 2 %)\n", 100.0 * worst);
}

}  // namespace
}  // namespace cosim::testing

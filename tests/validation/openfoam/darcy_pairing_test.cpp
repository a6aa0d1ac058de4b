// Darcy flow through a porous column on the MPM <-> OpenFOAM pairing
// (configs/openfoam_coupled/darcy; Tran et al., MPMICE, "Fluid flow through
// isothermal porous media"): water driven by dp through 1 m of grains held
// fixed (d = 1 mm) in a 2 m channel of 80 cells, run by MPPICInterFoam with
// the column as parcels whose Ergun-Wen-Yu drag is set to the job's
// Kozeny-Carman law. For the paper's five solid fractions and three pressure
// differences the steady pore-water velocity in the column is within 2 % of
//   U_f = (1/n) d^2 (1 - phi_s)^3 / (180 phi_s^2 mu) dp / L   (eq. 98).
// CI runs three cases from one corner of the table to the other (0.6 at
// 0.25 atm, 0.66 at 0.5 atm, 0.7 at 1 atm); -DCOSIM_FULL_VALIDATION=ON runs
// all 15 (~2.5 min).
// The porosity-zone fallback (interFoam) is run on two of the cases.
// Printed besides: the momentum the cloud gave the water in the last window
// (OpenFOAM's UTrans) against the drag law's, and the cell velocity in the
// free water upstream against n U_f (MPPICInterFoam's cell-centred velocity
// oscillates from cell to cell near a porosity jump while its face fluxes
// are uniform, so it is printed, not asserted).
//
// Needs OpenFOAM (openfoam_test_main.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <string>

#include "bench/darcy_column.hpp"
#include "replaced_text.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

using bench::DarcyColumn;

namespace fs = std::filesystem;

constexpr double atmosphere = 101325.0;

struct Steady {
  double column_velocity = 0.0;  // ux at the column's centre [m/s]
  double inlet_velocity = 0.0;   // ux in the free water upstream [m/s]
  double drift = 0.0;            // |change| of the column velocity over the last 0.02 s, relative
  double mismatch = 0.0;         // the cloud's momentum on the water against the law's
};

// `job_lines`: lines put after the job's `window:` line, and `water_lines`
// after the water participant's `executable:` line.
Steady run_case(const fs::path& dir, double phi_s, double dp, bool porosity_zones = false,
                const std::string& job_lines = "", const std::string& water_lines = "") {
  const fs::path source = fs::path(COSIM_SOURCE_DIR) / "configs/openfoam_coupled/darcy";
  fs::create_directories(dir);
  std::string job = read_text(source / "job.yaml");
  if (!job_lines.empty()) job = replaced(job, "window: 5.0e-3", "window: 5.0e-3\n" + job_lines);
  if (!water_lines.empty())
    job = replaced(job, "executable: openfoam_adapter",
                   "executable: openfoam_adapter\n    " + water_lines);
  write_text(dir / "job.yaml", job);
  write_text(dir / "column.yaml", replaced(read_text(source / "column.yaml"), "porosity: 0.4",
                                           fmt::format("porosity: {}", 1.0 - phi_s)));
  std::string water = replaced(read_text(source / "water.yaml"), "pressure: 151987.5",
                               fmt::format("pressure: {}", atmosphere + dp));
  if (porosity_zones)
    water = replaced(water, "solver: MPPICInterFoam",
                     "solver: interFoam\nsoil: {model: porosity_zones}");
  write_text(dir / "water.yaml", water);
  const ProcessResult r = run({binary("cosim").string(), "run", (dir / "job.yaml").string(),
                               "--output", (dir / "run").string()},
                              std::chrono::seconds(300));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // time, then p, p_rgh, ux, uy, water fraction per gauge: column, inlet
  const auto gauges = read_csv(dir / "run" / "water" / "gauges.csv");
  const auto exchange = read_csv(dir / "run" / "water" / "soil_exchange.csv");
  if (gauges.size() < 10 || exchange.empty()) {
    ADD_FAILURE() << "no gauge or exchange rows";
    return {};
  }
  const auto& last = gauges.back();
  Steady s{last[3], last[8], 0.0, exchange.back()[5]};
  for (const auto& row : gauges) {
    if (row[0] >= last[0] - 0.02 - 1e-9) {
      s.drift = std::abs(row[3] - last[3]) / std::abs(last[3]);
      break;
    }
  }
  return s;
}

TEST(OpenFoamDarcyPairing, PoreWaterVelocityMatchesEquation98ForAllFifteenCases) {
  const fs::path dir = fresh_directory("openfoam_darcy_pairing");
  double worst = 0.0, worst_mismatch = 0.0;
  const double fractions[] = {0.6, 0.62, 0.66, 0.68, 0.7};
  const double differences[] = {0.25, 0.5, 1.0};
  for (std::size_t i = 0; i < std::size(fractions); ++i) {
    const double phi_s = fractions[i];
    for (std::size_t j = 0; j < std::size(differences); ++j) {
#ifndef COSIM_FULL_VALIDATION
      if (i % 2 == 1 || j != i / 2) continue;
#endif
      const double atmospheres = differences[j];
      const double dp = atmospheres * atmosphere;
      const Steady s = run_case(dir / fmt::format("phi{}_dp{}", phi_s, atmospheres), phi_s, dp);
      const double exact = DarcyColumn{}.pore_velocity(phi_s, dp);
      const double error = std::abs(s.column_velocity / exact - 1.0);
      worst = std::max(worst, error);
      worst_mismatch = std::max(worst_mismatch, s.mismatch);
      fmt::print(
          "phi_s {:.2f}, dp {:.2f} atm: U_f {:.5f} m/s vs eq. 98 {:.5f} ({:+.3f} %, tolerance 2 "
          "%); drift over the last 0.02 s {:.1e}; cloud vs law momentum {:.2e}; free-water cell "
          "velocity vs n U_f {:+.1f} % (printed only)\n",
          phi_s, atmospheres, s.column_velocity, exact, 100.0 * (s.column_velocity / exact - 1.0),
          s.drift, s.mismatch, 100.0 * (s.inlet_velocity / ((1.0 - phi_s) * exact) - 1.0));
      EXPECT_LE(error, 0.02);
      EXPECT_LE(s.drift, 1e-3);  // steady
      // The soil's reaction comes from the law on the window's end fields;
      // OpenFOAM's own transfer in the last step must agree with it.
      EXPECT_LE(s.mismatch, 0.01);
    }
  }
  fmt::print(
      "largest error over the cases run: {:.3f} % (tolerance 2 %); largest momentum mismatch "
      "cloud vs law {:.2e} (tolerance 1e-2)\n",
      100.0 * worst, worst_mismatch);
}

// The fallback for rigid porous structures: interFoam with a porosity source
// on the column's cells (one zone: the column is uniform). Its velocity is
// superficial, without the cell-to-cell oscillation of MPPICInterFoam's, so
// the free water's flux n U_f is asserted too.
TEST(OpenFoamDarcyPairing, ThePorosityZoneFallbackGivesTheSameFlow) {
  const fs::path dir = fresh_directory("openfoam_darcy_porosity_zones");
  for (const auto& [phi_s, atmospheres] : {std::pair{0.6, 0.5}, std::pair{0.7, 1.0}}) {
    const double dp = atmospheres * atmosphere;
    const Steady s = run_case(dir / fmt::format("phi{}_dp{}", phi_s, atmospheres), phi_s, dp, true);
    const double exact = DarcyColumn{}.pore_velocity(phi_s, dp);
    const double error = s.column_velocity / exact - 1.0;
    const double flux_error = s.inlet_velocity / ((1.0 - phi_s) * exact) - 1.0;
    fmt::print(
        "porosity zones: phi_s {:.2f}, dp {:.2f} atm: U_f {:.5f} m/s vs eq. 98 {:.5f} ({:+.3f} %, "
        "tolerance 2 %); free-water flux vs n U_f {:+.3f} % (tolerance 2 %)\n",
        phi_s, atmospheres, s.column_velocity, exact, 100.0 * error, 100.0 * flux_error);
    EXPECT_LE(std::abs(error), 0.02);
    EXPECT_LE(std::abs(flux_error), 0.02);
    EXPECT_LE(s.drift, 1e-3);
  }
}

// The water's `ranks: 2` runs OpenFOAM on two processes (the adapter is one
// process and decomposes the case itself, openfoam_adapter's backend
// descriptor says `ranks: solver_processes`), on either transport. The
// decomposed run gives the serial run's flow to OpenFOAM's sums (its
// parallel reductions change the last digits); both transports give the
// same bits.
TEST(OpenFoamDarcyPairing, TheWatersRanksAreOpenFoamsProcessesOnEitherTransport) {
  const fs::path dir = fresh_directory("openfoam_darcy_ranks");
  const double phi_s = 0.6, dp = 0.5 * atmosphere;
  const Steady serial = run_case(dir / "serial", phi_s, dp);
  const Steady zmq = run_case(dir / "zmq", phi_s, dp, false, "", "ranks: 2");
  const Steady mpi = run_case(dir / "mpi", phi_s, dp, false, "transport: mpi", "ranks: 2");
  for (const char* run : {"zmq", "mpi"}) {
    const fs::path water = dir / run / "run" / "water";
    EXPECT_TRUE(fs::is_directory(water / "case" / "processor1")) << run;
    EXPECT_FALSE(fs::exists(water / "case" / "processor2")) << run;
    EXPECT_NE(read_text(water / "summary.json").find("\"processes\": 2"), std::string::npos) << run;
  }
  const double difference = std::abs(zmq.column_velocity / serial.column_velocity - 1.0);
  fmt::print(
      "U_f on one OpenFOAM process {:.9f} m/s, on two {:.9f} m/s (ZeroMQ) and {:.9f} m/s (MPI): "
      "relative difference {:.2e} (tolerance 1e-6), MPI against ZeroMQ {:.2e} (tolerance 0)\n",
      serial.column_velocity, zmq.column_velocity, mpi.column_velocity, difference,
      std::abs(mpi.column_velocity - zmq.column_velocity));
  EXPECT_LE(difference, 1e-6);
  EXPECT_EQ(mpi.column_velocity, zmq.column_velocity);
  EXPECT_EQ(mpi.mismatch, zmq.mismatch);
}

}  // namespace
}  // namespace cosim::testing

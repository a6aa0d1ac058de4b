// Pan et al. 2021, Sec. 4.2 (Table 2): the collapse of a submerged granular
// column (Rondon et al.'s experiment) on the MPM <-> OpenFOAM pairing
// (configs/openfoam_coupled/granular_collapse). The paper compares the
// deposit with the experiment in a figure only, so this checks what the
// physics demands and prints the numbers.
//
// CI runs the first 0.01 s: the column starts from its geostatic effective
// stress, so the open water must stay hydrostatic, the water under the
// releasing column a little below, and the water's volume be kept;
// -DCOSIM_FULL_VALIDATION=ON runs
// the paper's 2 s (~1.5 h): the column must spread beyond the gate, lose
// height, and come to rest. The job used to fail at t = 0.91 s after its
// free surface grew unstable, which OpenFOAM's restarts caused; since they
// keep the solver's inertia it runs on (examples/granular_collapse/README.md).
//
// Needs OpenFOAM (openfoam_test_main.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_smoke_run.hpp"
#include "hdf5_reader.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr double still_water = 0.12;  // h0 [m]
constexpr double gauge_height = 0.0025;
constexpr double hydrostatic = 1000.0 * 9.81 * (still_water - gauge_height);  // [Pa]

TEST(OpenFoamGranularCollapse, TheColumnSitsInHydrostaticWaterAndSpreads) {
#ifdef COSIM_FULL_VALIDATION
  const double end_time = 2.0;
#else
  const double end_time = 0.01;
#endif
  // seed001's bench-smoke test runs the job (configs/bench/seed001.yaml) to end_time.
  const fs::path run = bench_smoke_run("seed001", "granular_collapse", "openfoam");

  // time, then p, p_rgh, ux, uy, water fraction at the column's base and in
  // the open water, then the three wave gauges' surface elevation
  const auto gauges = read_csv(run / "water" / "gauges.csv");
  ASSERT_FALSE(gauges.empty());
  EXPECT_NEAR(gauges.back()[0], end_time, 1e-6) << "the bench's run ends at another time";
  ASSERT_GE(gauges.size(), 50u);
  ASSERT_EQ(gauges.front().size(), 14u);
  const auto& last = gauges.back();
  const double base_error = last[1] / hydrostatic - 1.0;
  const double open_error = last[6] / hydrostatic - 1.0;
  fmt::print(
      "pore pressure at t = {:.3f} s, y = {} m: column base {:.1f} Pa ({:+.2f} %), open "
      "water {:.1f} Pa ({:+.2f} %), hydrostatic {:.1f} Pa (open water: tolerance 2 %)\n",
      last[0], gauge_height, last[1], 100.0 * base_error, last[6], 100.0 * open_error, hydrostatic);
  const auto exchange = read_csv(run / "water" / "soil_exchange.csv");
  ASSERT_FALSE(exchange.empty());
  fmt::print(
      "cloud vs law momentum in the last window: {:.2e} (printed only: at one step per "
      "window the cloud drags with the window's start velocity, the law with its end's)\n",
      exchange.back()[5]);
  const auto water = nlohmann::json::parse(read_text(run / "water" / "summary.json"))["conserved"];
  const double start = water["volume_water"]["start"].get<double>();
  const double end = water["volume_water"]["end"].get<double>();
  fmt::print("water volume {:.6f} -> {:.6f} m^2 ({:+.2e}; tolerance 1e-2)\n", start, end,
             end / start - 1.0);
  EXPECT_LE(std::abs(end / start - 1.0), 1e-2);

  const auto soil = nlohmann::json::parse(read_text(run / "soil" / "summary.json"));
  const double mass = soil["conserved"]["mass"]["end"].get<double>();
  const double mass_start = soil["conserved"]["mass"]["start"].get<double>();
  EXPECT_NEAR(mass, mass_start, 1e-12 * mass_start);
  fmt::print("soil: {} capped and {} overfilled exchange cells over {} writes\n",
             soil["coupling"]["capped_solid_fraction_cells"].get<long>(),
             soil["coupling"]["overfilled_cells"].get<long>(),
             soil["coupling"]["writes"].get<long>());
#ifdef COSIM_FULL_VALIDATION
  // At rest again: the pore water is hydrostatic once more under the deposit.
  EXPECT_LE(std::abs(base_error), 0.05);
  EXPECT_LE(std::abs(open_error), 0.02);
  fs::path snapshot;
  for (const auto& entry : fs::directory_iterator(run / "soil"))
    if (entry.path().extension() == ".h5" && entry.path() > snapshot) snapshot = entry.path();
  ASSERT_FALSE(snapshot.empty());
  const auto xyz = Hdf5Reader(snapshot).doubles("geometry/xyz").values;  // 3 per point
  double front = 0.0, top = 0.0;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
    front = std::max(front, xyz[i]);
    top = std::max(top, xyz[i + 1]);
  }
  fmt::print(
      "deposit at t = 2 s: front x = {:.4f} m (gate at 0.06 m), top y = {:.4f} m (column "
      "0.08 m)\n",
      front, top);
  EXPECT_GT(front, 0.09);
  EXPECT_LT(top, 0.075);
#else
  EXPECT_LE(std::abs(open_error), 0.02);
  // Under the column the water is below hydrostatic (measured -7.8 % at
  // 0.01 s): the releasing skeleton dilates (its mean porosity 0.45 ->
  // 0.4501 by then, ~2e-4 of its volume) and draws water in through pores of
  // k = 1.5e-10 m^2; Darcy asks ~800 Pa for the whole inflow. The bound
  // catches a sign or scale error of the coupling, not the physics' detail.
  EXPECT_LE(base_error, 0.0);
  EXPECT_GE(base_error, -0.2);
#endif
}

}  // namespace
}  // namespace cosim::testing

// Martin & Moyce (1952) dam break run by stock OpenFOAM (interFoam) through
// openfoam_adapter (configs/openfoam/martin_moyce.yaml): the same case, the
// same front measure and the same tolerances as the ICE solver's validation
// (tests/validation/ice/martin_moyce_test.cpp), so the two fluid backends
// are compared on one case. The front is the downstream edge of the last
// cell of the floor row holding more water than air, in each snapshot.
// The run is the verification bench suite's (configs/bench/verification.yaml,
// scenario martin_moyce), which its bench-smoke test runs first.
//
// Needs OpenFOAM (openfoam_test_main.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench_smoke_run.hpp"
#include "hdf5_reader.hpp"
#include "martin_moyce/surge_front.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace {

namespace fs = std::filesystem;
namespace mm = cosim::testing::martin_moyce;

constexpr int cells_x = 100;
constexpr double length_x = 0.28575;

double sum_of(const nlohmann::json& values) {
  double total = 0.0;
  for (const auto& v : values) total += v.get<double>();
  return total;
}

TEST(OpenFoamMartinMoyce, SurgeFrontFollowsTheExperimentLikeTheIceSolver) {
  const std::vector<mm::Point> measured =
      mm::experiment_front(std::string(COSIM_REFERENCE_DATA) + "/martin_moyce_1952.csv");
  ASSERT_GE(measured.size(), 10u);
  const fs::path output =
      cosim::testing::bench_smoke_run("verification", "martin_moyce", "openfoam");

  const double a = mm::column_width;
  const double dx = length_x / cells_x;
  std::vector<mm::Point> front;
  double water_start = 0.0, water_end = 0.0;
  for (std::size_t step = 0;; ++step) {
    const fs::path file = output / fmt::format("openfoam_{:06d}.h5", step);
    if (!fs::exists(file)) break;
    cosim::testing::Hdf5Reader h5(file);
    const auto alpha = h5.doubles("/fields/alpha_water");
    ASSERT_EQ(alpha.dims.size(), 2u);
    ASSERT_EQ(alpha.dims[1], static_cast<hsize_t>(cells_x));
    double edge = 0.0;
    for (int i = 0; i < cells_x; ++i) {
      if (alpha.values[static_cast<std::size_t>(i)] > 0.5) edge = (i + 1) * dx;
    }
    front.push_back({h5.root_double("time") * mm::time_scale(), edge / a});
    double water = 0.0;
    for (double v : alpha.values) water += v;
    (step == 0 ? water_start : water_end) = water;
  }
  ASSERT_GE(front.size(), 30u) << "snapshots in " << output;
  ASSERT_NEAR(front.front().value, 1.0, 1e-12);
  const mm::Comparison c = mm::SurgeFront(front).compare(measured);
  ASSERT_GT(c.measured_speed, 0.0);
  const double water_change = std::abs(water_end - water_start) / water_start;

  const auto summary = nlohmann::json::parse(cosim::testing::read_text(output / "summary.json"));
  const auto& windows = summary["openfoam_windows"];
  const double startup = sum_of(windows["solver_startup_s"]);
  const double stepping = sum_of(windows["solver_stepping_s"]);
  const double files = sum_of(windows["adapter_write_s"]) + sum_of(windows["field_read_s"]);
  fmt::print(
      "OpenFOAM interFoam: largest front error {:.1f} % for T <= 3 (issue target 10 %); front "
      "speed {:.3f} vs {:.3f} ({:+.1f} %, tolerance 10 %); fitted time offset {:.3f} leaves "
      "{:.1f} % (tolerance 10 %); water volume change {:.1e} (tolerance 1e-3); {} windows: "
      "start-up {:.2f} s, stepping {:.2f} s, adapter files {:.3f} s\n",
      100.0 * c.largest_error, c.simulated_speed, c.measured_speed,
      100.0 * (c.simulated_speed / c.measured_speed - 1.0), c.offset,
      100.0 * c.largest_error_offset, water_change, windows["end_time_s"].size(), startup, stepping,
      files);
  EXPECT_LE(water_change, 1e-3);
  EXPECT_NEAR(c.simulated_speed, c.measured_speed, 0.10 * c.measured_speed);
  EXPECT_LE(c.offset, 0.35);
  EXPECT_LE(c.largest_error_offset, 0.10);
}

}  // namespace

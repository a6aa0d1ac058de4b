// Natural convection in a square porous cavity heated from the side on the
// MPM <-> ICE pairing with the drag solved by ice_fluid and the energy
// exchange by the coupler (configs/ice_coupled/thermal_cavity; Tran et al.,
// MPMICE, "Thermal induced cavity flow"), at the Darcy-Rayleigh number
//   Ra = g beta K dT H / (nu alpha_m) = 100
// of the setup (H = 5.655 m with the paper's grains, water and dT = 1 K).
// At steady state the mean Nusselt number at the hot and at the cold wall,
// Nu = -(H / dT) mean dT/dx (second-order one-sided from the wall and the
// first two cells), is within 5 % of the literature's 3.10 (Walker & Homsy
// 1978: 3.097; Manole & Lage 1992: 3.118; Gross et al. 1986: 3.141); the two
// walls pass the same heat (0.5 %) and the last two snapshots agree (1e-3).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "hdf5_reader.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

constexpr int cells = 40;
constexpr double height = 5.655, hot = 293.65, cold = 292.65;

struct Nusselt {
  double time = 0.0, hot_wall = 0.0, cold_wall = 0.0;
};

Nusselt nusselt(const fs::path& snapshot) {
  const Hdf5Reader file(snapshot);
  const auto t = file.doubles("fields/temperature_water").values;  // x fastest
  const double dx = height / cells;
  Nusselt nu;
  nu.time = file.root_double("time");
  for (int j = 0; j < cells; ++j) {
    const auto at = [&](int i) { return t[static_cast<std::size_t>(j * cells + i)]; };
    nu.hot_wall -= (-8.0 * hot + 9.0 * at(0) - at(1)) / (3.0 * dx);
    nu.cold_wall -= (8.0 * cold - 9.0 * at(cells - 1) + at(cells - 2)) / (3.0 * dx);
  }
  nu.hot_wall *= height / (hot - cold) / cells;
  nu.cold_wall *= height / (hot - cold) / cells;
  return nu;
}

TEST(ThermalCavity, NusseltNumberMatchesTheLiteratureAtRa100) {
  const double g = 9.81, beta = 2.1e-4, d = 1e-3, n = 0.4, phi_s = 0.6;
  const double permeability = d * d * n * n * n / (180.0 * phi_s * phi_s);
  const double k_m = n * 0.598 + phi_s * 0.4;
  const double alpha_m = k_m / (998.2 * 4181.0), nu_w = 1.0e-3 / 998.2;
  const double rayleigh = g * beta * permeability * (hot - cold) * height / (nu_w * alpha_m);
  const fs::path dir = fresh_directory("thermal_cavity");
  const ProcessResult r =
      run({binary("cosim").string(), "run",
           (fs::path(COSIM_SOURCE_DIR) / "configs/ice_coupled/thermal_cavity/job.yaml").string(),
           "--output", (dir / "run").string()},
          std::chrono::seconds(900));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<fs::path> snapshots;
  for (const auto& entry : fs::directory_iterator(dir / "run" / "water")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ice_", 0) == 0 && entry.path().extension() == ".h5")
      snapshots.push_back(entry.path());
  }
  std::sort(snapshots.begin(), snapshots.end());
  ASSERT_GE(snapshots.size(), 3u);
  const Nusselt last = nusselt(snapshots.back());
  const Nusselt before = nusselt(snapshots[snapshots.size() - 2]);
  constexpr double literature = 3.10;
  fmt::print(
      "Ra = {:.2f}: Nu at t = {:.3g} s hot wall {:.4f}, cold wall {:.4f} vs literature {:.2f} "
      "({:+.2f} %, tolerance 5 %); at t = {:.3g} s {:.4f}\n",
      rayleigh, last.time, last.hot_wall, last.cold_wall, literature,
      100.0 * (last.hot_wall / literature - 1.0), before.time, before.hot_wall);
  EXPECT_NEAR(rayleigh, 100.0, 0.5);
  EXPECT_NEAR(last.hot_wall, literature, 0.05 * literature);
  EXPECT_NEAR(last.cold_wall, last.hot_wall, 0.005 * last.hot_wall);
  EXPECT_NEAR(last.hot_wall, before.hot_wall, 1e-3 * last.hot_wall);
  const auto coupler = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_LE(coupler["metrics"]["max_energy_exchange_balance_error"]["value"].get<double>(), 1e-12);
}

}  // namespace
}  // namespace cosim::testing

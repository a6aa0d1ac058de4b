#include "swe/two_phase/fluid_sources.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "input_error.hpp"

namespace swe {
namespace {

constexpr double area = 2.5;

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(SweFluidSources, KeepsTheVolumeBalanceToRoundOffAndDepthsNonNegative) {
  const std::size_t n = 64;
  std::vector<double> h(n), hu(n), hv(n);
  SolidLayer layer = empty_solid_layer(n, 2000.0);
  layer.released_fluid_rate.assign(n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const double s = static_cast<double>(c);
    // some cells dry, some shallower than what infiltration takes in a step
    h[c] = c % 5 == 0 ? 0.0 : 1e-4 * std::fmod(7.3 * s, 13.0);
    hu[c] = h[c] * std::sin(s);
    hv[c] = h[c] * std::cos(s);
    layer.velocity_x[c] = 0.5 * std::cos(0.3 * s);
    layer.velocity_y[c] = -0.2;
    if (c % 3 == 0) layer.released_fluid_rate[c] = 1e-4 * s;
  }
  const UniformSources sources{.rain_rate = 2e-5, .infiltration_rate = 1e-3};
  double worst = 0.0, infiltrated = 0.0;
  for (int step = 0; step < 20; ++step) {
    const double before = sum(h) * area;
    const SourceVolumes v = add_sources(sources, layer, area, 0.37, h, hu, hv);
    const double after = sum(h) * area;
    worst = std::max(worst, std::abs(after - (before + v.added - v.infiltrated)) /
                                std::max({before, v.added, v.infiltrated}));
    infiltrated += v.infiltrated;
    for (std::size_t c = 0; c < n; ++c) ASSERT_GE(h[c], 0.0) << "cell " << c;
  }
  const auto emptied = std::count(h.begin(), h.end(), 0.0);
  fmt::print(
      "fluid sources, {} cells x 20 steps ({} emptied by infiltration): volume after - "
      "(before + added - infiltrated), relative {:.2e} (tolerance 1e-14)\n",
      n, emptied, worst);
  EXPECT_GT(emptied, 0);
  EXPECT_GT(infiltrated, 0.0);
  EXPECT_LE(worst, 1e-14);
}

TEST(SweFluidSources, ReleasedFluidCarriesTheSolidsVelocityAndRainNone) {
  std::vector<double> h{0.5, 0.5}, hu{0.1, 0.1}, hv{0.0, 0.0};
  SolidLayer layer = empty_solid_layer(2, 2000.0);
  layer.velocity_x = {2.0, 2.0};
  layer.velocity_y = {-1.0, -1.0};
  layer.released_fluid_rate = {0.5, 0.0};  // m^3/s
  const SourceVolumes v =
      add_sources({.rain_rate = 0.01, .infiltration_rate = 0.0}, layer, area, 2.0, h, hu, hv);
  // cell 0: 1 m^3 over 2.5 m^2 = 0.4 m with (2, -1) m/s, and 0.02 m of rain
  EXPECT_NEAR(h[0], 0.92, 1e-15);
  EXPECT_NEAR(hu[0], 0.1 + 0.8, 1e-15);
  EXPECT_NEAR(hv[0], -0.4, 1e-15);
  // cell 1: rain only, the discharge unchanged (the velocity falls)
  EXPECT_NEAR(h[1], 0.52, 1e-15);
  EXPECT_EQ(hu[1], 0.1);
  EXPECT_NEAR(v.added, 1.0 + 2 * 0.02 * area, 1e-14);
}

TEST(SweFluidSources, InfiltrationTakesTheWaterWithItsVelocityAndNoMoreThanThere) {
  std::vector<double> h{0.5, 0.001}, hu{0.5, 0.003}, hv{0.25, 0.0};
  const SolidLayer layer = empty_solid_layer(2, 2000.0);
  const SourceVolumes v =
      add_sources({.rain_rate = 0.0, .infiltration_rate = 0.01}, layer, area, 1.0, h, hu, hv);
  EXPECT_NEAR(h[0], 0.49, 1e-15);
  EXPECT_NEAR(hu[0] / h[0], 1.0, 1e-15);
  EXPECT_NEAR(hv[0] / h[0], 0.5, 1e-15);
  EXPECT_EQ(h[1], 0.0);
  EXPECT_EQ(hu[1], 0.0);
  EXPECT_NEAR(v.infiltrated, (0.01 + 0.001) * area, 1e-16);
}

TEST(SweFluidSources, RefusesNegativeRates) {
  std::vector<double> h{0.5}, hu{0.0}, hv{0.0};
  const SolidLayer layer = empty_solid_layer(1, 2000.0);
  const std::string message = cosim::testing::input_error_message([&] {
    add_sources({.rain_rate = -1.0, .infiltration_rate = 0.0}, layer, area, 1.0, h, hu, hv);
  });
  EXPECT_NE(message.find("rain rate"), std::string::npos) << message;
}

}  // namespace
}  // namespace swe

#include "mpm/depth_averaged/earth_pressure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

TEST(EarthPressure, RankinesCoefficientsAreActiveWhereTheColumnSpreadsAndPassiveWhereItNarrows) {
  const EarthPressure rankine(EarthPressureModel::rankine);
  EXPECT_NEAR(rankine.coefficient(30.0 * deg, 0.1), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(rankine.coefficient(30.0 * deg, -0.1), 3.0, 1e-14);
  EXPECT_DOUBLE_EQ(EarthPressure(EarthPressureModel::isotropic).coefficient(30.0 * deg, -1.0), 1.0);
}

TEST(EarthPressure, ACohesionlessThrustIsSavageAndHuttersHalfKGammaHSquared) {
  EXPECT_DOUBLE_EQ(EarthPressure::thrust(0.5, 2.0e4, 0.0, 3.0), 0.5 * 0.5 * 2.0e4 * 9.0);
}

// Bell's lateral stress K gamma (h - z) - 2 c sqrt(K) integrated where it is
// compressive equals the closed form.
TEST(EarthPressure, BellsCohesiveThrustIsItsCompressivePartIntegratedOverTheDepth) {
  const double K = 0.4, gamma = 1.8e4, c = 5.0e3, h = 4.0;
  const double z_c = EarthPressure::crack_depth(K, gamma, c);
  EXPECT_NEAR(K * gamma * z_c - 2.0 * c * std::sqrt(K), 0.0, 1e-9);
  const int n = 200000;
  double integral = 0.0;
  for (int k = 0; k < n; ++k) {
    const double depth_below_top = (k + 0.5) * h / n;
    integral += std::max(0.0, K * gamma * depth_below_top - 2.0 * c * std::sqrt(K)) * h / n;
  }
  EXPECT_NEAR(EarthPressure::thrust(K, gamma, c, h), integral, 1e-6 * integral);
  EXPECT_EQ(EarthPressure::thrust(K, gamma, c, 0.9 * z_c), 0.0);
}

TEST(EarthPressure, AnUnknownModelIsRefusedByName) {
  EXPECT_EQ(earth_pressure_model_from("rankine"), EarthPressureModel::rankine);
  EXPECT_THROW(earth_pressure_model_from("coulomb"), std::invalid_argument);
}

}  // namespace
}  // namespace mpm

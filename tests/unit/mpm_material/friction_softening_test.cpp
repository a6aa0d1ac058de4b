#include "mpm/material/friction_softening.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mpm/material/rowe_dilatancy.hpp"

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

TEST(FrictionSoftening, FallsMonotonicallyAndContinuouslyFromPeakToResidual) {
  const FrictionSoftening law(45 * deg, 10 * deg, 20.0, FrictionSoftening::Dilatancy::rowe, 0.0);
  EXPECT_DOUBLE_EQ(law.friction_angle(0.0), 45 * deg);
  double previous = law.friction_angle(0.0);
  const double step = 1e-4;
  for (double eps = step; eps < 2.0; eps += step) {
    const double phi = law.friction_angle(eps);
    EXPECT_LE(phi, previous);
    if (eps < 0.5) {
      EXPECT_LT(phi, previous);
    }
    EXPECT_LT(previous - phi, 20.0 * 35 * deg * step * 1.0001);  // Lipschitz: continuous
    EXPECT_GE(phi, 10 * deg);
    previous = phi;
  }
  EXPECT_NEAR(law.friction_angle(2.0), 10 * deg, 1e-15 + 35 * deg * std::exp(-40.0));
  EXPECT_NEAR(law.friction_angle(1e6), 10 * deg, 1e-15);
}

TEST(FrictionSoftening, RoweDilationIsZeroAtResidualAndPositiveBefore) {
  const FrictionSoftening law(45 * deg, 10 * deg, 20.0, FrictionSoftening::Dilatancy::rowe, 0.0);
  EXPECT_NEAR(law.dilation_angle(10 * deg), 0.0, 1e-15);
  EXPECT_GT(law.dilation_angle(10.5 * deg), 0.0);
  EXPECT_EQ(law.dilation_angle(5 * deg), 0.0);  // clamped
  const double peak = law.dilation_angle(45 * deg);
  EXPECT_NEAR(
      std::sin(peak),
      (std::sin(45 * deg) - std::sin(10 * deg)) / (1 - std::sin(10 * deg) * std::sin(45 * deg)),
      1e-15);
  EXPECT_LT(peak, 45 * deg);
  double previous = 0.0;
  for (double phi = 10 * deg; phi <= 45 * deg; phi += 0.1 * deg) {
    const double psi = rowe_dilation_angle(phi, 10 * deg);
    EXPECT_GE(psi, previous);
    previous = psi;
  }
}

TEST(FrictionSoftening, ConstantDilationIsCappedAtTheMobilisedFriction) {
  const FrictionSoftening law(40 * deg, 20 * deg, 10.0, FrictionSoftening::Dilatancy::constant,
                              25 * deg);
  EXPECT_DOUBLE_EQ(law.dilation_angle(40 * deg), 25 * deg);
  EXPECT_DOUBLE_EQ(law.dilation_angle(22 * deg), 22 * deg);
}

TEST(FrictionSoftening, NoRateMeansNoSoftening) {
  const FrictionSoftening law(30 * deg, 30 * deg, 0.0, FrictionSoftening::Dilatancy::constant, 0.0);
  EXPECT_DOUBLE_EQ(law.friction_angle(100.0), 30 * deg);
}

}  // namespace
}  // namespace mpm

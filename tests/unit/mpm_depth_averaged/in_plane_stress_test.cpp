#include "mpm/depth_averaged/in_plane_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mpm {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

TEST(InPlaneStress, StretchingAlongXIsPlaneStressElasticity) {
  const InPlaneStress s{.youngs_modulus = 1e7, .poisson_ratio = 0.25};
  Mat<2> L = Mat<2>::Zero();
  L(0, 0) = 1e-3;
  const Mat<2> sigma = s.elastic_update(Mat<2>::Zero(), L, 0.5);
  const double plane = 1e7 / (1.0 - 0.0625);
  EXPECT_NEAR(sigma(0, 0), plane * 5e-4, 1e-9);
  EXPECT_NEAR(sigma(1, 1), 0.25 * plane * 5e-4, 1e-9);
  EXPECT_EQ(sigma(0, 1), 0.0);
  EXPECT_NEAR(s.wave_speed(2000.0), std::sqrt(plane / 2000.0), 1e-12);
  EXPECT_EQ(InPlaneStress{}.wave_speed(2000.0), 0.0);
  EXPECT_FALSE(InPlaneStress{}.enabled());
}

TEST(InPlaneStress, ASpinRotatesTheStressWithoutStrainingIt) {
  const InPlaneStress s{.youngs_modulus = 1e7, .poisson_ratio = 0.3};
  Mat<2> sigma;
  sigma << 3e4, 1e4, 1e4, -2e4;
  Mat<2> spin;
  spin << 0.0, -0.2, 0.2, 0.0;  // a rigid rotation at 0.2 rad/s
  const Mat<2> rotated = s.elastic_update(sigma, spin, 1e-3);
  EXPECT_NEAR(rotated.trace(), sigma.trace(), 1e-9);
  EXPECT_NEAR(rotated.determinant(), sigma.determinant(), 1e-6 * std::abs(sigma.determinant()));
  EXPECT_NEAR(rotated(0, 1), rotated(1, 0), 1e-9);
  EXPECT_GT((rotated - sigma).norm(), 1.0);  // it did turn
}

TEST(InPlaneStress, MohrCoulombBoundsTheStressAtItsMean) {
  const double c = 1e4, phi = 30.0 * deg;
  bool yielded = true;
  // Inside: unchanged.
  Mat<2> inside;
  inside << -2e4, 2e3, 2e3, -1e4;
  EXPECT_EQ(InPlaneStress::bounded(inside, c, phi, yielded), inside);
  EXPECT_FALSE(yielded);
  // Too much shear at a compressive mean of -1e4: the radius comes down to
  // c cos(phi) - mean sin(phi), the mean stays.
  Mat<2> shear;
  shear << -1e4 + 3e4, 0.0, 0.0, -1e4 - 3e4;
  const Mat<2> b = InPlaneStress::bounded(shear, c, phi, yielded);
  EXPECT_TRUE(yielded);
  EXPECT_NEAR(0.5 * b.trace(), -1e4, 1e-9);
  EXPECT_NEAR(0.5 * (b(0, 0) - b(1, 1)), c * std::cos(phi) + 1e4 * std::sin(phi), 1e-9);
  // Pulled apart beyond the apex c / tan(phi): the apex.
  const Mat<2> pulled = InPlaneStress::bounded(Mat<2>::Identity() * 3e4, c, phi, yielded);
  EXPECT_TRUE(yielded);
  EXPECT_NEAR((pulled - Mat<2>::Identity() * c / std::tan(phi)).norm(), 0.0, 1e-9);
  // phi = 0: Tresca, and tension cut off at c.
  const Mat<2> cut = InPlaneStress::bounded(Mat<2>::Identity() * 3e4, c, 0.0, yielded);
  EXPECT_TRUE(yielded);
  EXPECT_NEAR(cut(0, 0), c, 1e-9);
  EXPECT_NEAR(cut(1, 1), c, 1e-9);
}

}  // namespace
}  // namespace mpm

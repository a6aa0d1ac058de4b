#include <gtest/gtest.h>

#include "swe/numerics/hydrostatic_reconstruction.hpp"
#include "swe/numerics/manning_friction.hpp"
#include "swe/numerics/slope_limiter.hpp"

namespace {

constexpr double g = 9.81;

TEST(HydrostaticFace, BalancesALakeAtRestAcrossABedStep) {
  // Free surface at 1 m over beds 0.2 m and 0.5 m: both sides see the depth
  // over the higher bed, and each side's corrected momentum flux is its own
  // hydrostatic pressure g h^2 / 2.
  const swe::HydrostaticFace f = swe::hydrostatic_face(0.8, 0.2, 0.5, 0.5, g);
  EXPECT_DOUBLE_EQ(f.h_left, 0.5);
  EXPECT_DOUBLE_EQ(f.h_right, 0.5);
  EXPECT_DOUBLE_EQ(0.5 * g * 0.25 + f.left_correction, 0.5 * g * 0.64);
  EXPECT_DOUBLE_EQ(0.5 * g * 0.25 + f.right_correction, 0.5 * g * 0.25);
}

TEST(HydrostaticFace, SeesNoWaterAgainstAnEmergedBed) {
  const swe::HydrostaticFace f = swe::hydrostatic_face(0.3, 0.0, 0.0, 0.6, g);
  EXPECT_EQ(f.h_left, 0.0);
  EXPECT_EQ(f.h_right, 0.0);
  EXPECT_DOUBLE_EQ(f.left_correction, 0.5 * g * 0.09);
}

TEST(CellBedSource, CancelsTheFacePressuresOfAReconstructedLakeAtRest) {
  // Surface 1 m, bed 0.1 m at the lower face and 0.3 m at the upper face.
  const double h_minus = 0.9, h_plus = 0.7;
  const double s = swe::cell_bed_source(h_minus, 0.1, h_plus, 0.3, g);
  EXPECT_NEAR(0.5 * g * h_plus * h_plus - 0.5 * g * h_minus * h_minus, s, 1e-15);
}

TEST(SlopeLimiter, IsZeroAtExtremaAndBoundedOtherwise) {
  for (auto kind : {swe::LimiterKind::minmod, swe::LimiterKind::van_leer,
                    swe::LimiterKind::monotonized_central}) {
    EXPECT_EQ(swe::limited_slope(kind, 1.0, -1.0), 0.0) << swe::to_string(kind);
    EXPECT_DOUBLE_EQ(swe::limited_slope(kind, 0.5, 0.5), 0.5) << swe::to_string(kind);
    const double s = swe::limited_slope(kind, 0.1, 1.0);
    EXPECT_GT(s, 0.0);
    EXPECT_LE(s, 2.0 * 0.1 + 1e-15) << swe::to_string(kind);
  }
  EXPECT_EQ(swe::limited_slope(swe::LimiterKind::none, 1.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(swe::limited_slope(swe::LimiterKind::minmod, 0.1, 1.0), 0.1);
}

TEST(ManningFriction, ShrinksMomentumAsEquation36) {
  const double h = 0.5, u = 2.0, n = 0.03, dt = 0.01;
  const double factor = swe::manning_factor(h, u, g, n, dt);
  EXPECT_NEAR(factor, 1.0 / (1.0 + dt * g * n * n * u / std::pow(h, 4.0 / 3.0)), 1e-15);
  EXPECT_LT(factor, 1.0);
  EXPECT_EQ(swe::manning_factor(0.0, u, g, n, dt), 1.0);
  EXPECT_EQ(swe::manning_factor(h, u, g, 0.0, dt), 1.0);
  EXPECT_NEAR(swe::manning_bed_shear(h, u, u, g, n, 1000.0),
              1000.0 * g * n * n * u * u / std::cbrt(h), 1e-9);
}

}  // namespace

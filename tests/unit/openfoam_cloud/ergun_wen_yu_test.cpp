#include "openfoam/cloud/ergun_wen_yu.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cosim/error.hpp"

namespace openfoam {
namespace {

constexpr double mu = 1.0e-3;

TEST(ErgunWenYu, InTheDarcyLimitIsErgunsPackedBedLaw) {
  // phi_s = 0.6, no relative motion: K = 150 phi_s^2 mu / (n^2 d^2).
  const CloudDragInput at_rest{0.6, 1000.0, mu, 0.0};
  const double d = 1.0e-3;
  EXPECT_NEAR(ergun_wen_yu_coefficient(at_rest, d), 150.0 * 0.36 * mu / (0.16 * d * d), 1e-6);
}

TEST(ErgunWenYu, ErgunsInertialTermGrowsWithTheReynoldsNumber) {
  // Re = rho |U| d / mu = 100: 150 phi_s / n = 225 plus 1.75 Re = 175.
  const double d = 1.0e-3;
  const CloudDragInput moving{0.6, 1000.0, mu, 0.1};
  EXPECT_NEAR(
      ergun_wen_yu_coefficient(moving, d) / ergun_wen_yu_coefficient({0.6, 1000.0, mu, 0.0}, d),
      (225.0 + 175.0) / 225.0, 1e-12);
}

TEST(ErgunWenYu, DiluteCellsTakeWenAndYusSphereDrag) {
  // n = 0.9, Re -> 0: K = phi_s 0.75 24 mu n^-2.65 / (n d^2) = 18 phi_s mu n^-3.65 / d^2.
  const double d = 2.0e-4;
  EXPECT_NEAR(ergun_wen_yu_coefficient({0.1, 1000.0, mu, 0.0}, d) /
                  (18.0 * 0.1 * mu * std::pow(0.9, -3.65) / (d * d)),
              1.0, 1e-12);
}

TEST(ErgunWenYu, TheGrainSizeGivesBackTheCoefficientAtAnySpeed) {
  for (double phi_s : {0.05, 0.3, 0.6, 0.7}) {
    for (double speed : {0.0, 1e-3, 0.1, 2.0}) {
      const CloudDragInput in{phi_s, 998.0, mu, speed};
      const double target = 4.05e5;
      const double d = ergun_wen_yu_grain_size(in, target);
      EXPECT_NEAR(ergun_wen_yu_coefficient(in, d) / target, 1.0, 1e-9)
          << "phi_s " << phi_s << ", speed " << speed;
    }
  }
}

TEST(ErgunWenYu, TheKozenyCarmanGrainMatchesInTheDarcySense) {
  // The cloud's water takes the whole pressure gradient, so it needs K / n:
  // Kozeny-Carman's K = 180 phi_s^2 mu / (d^2 n) at rest is matched by
  // d sqrt(150 / 180).
  const double phi_s = 0.6, n = 0.4, d = 1.0e-3;
  const double k = 180.0 * phi_s * phi_s * mu / (d * d * n);
  EXPECT_NEAR(
      ergun_wen_yu_grain_size({phi_s, 1000.0, mu, 0.0}, k / n) / (d * std::sqrt(150.0 / 180.0)),
      1.0, 1e-9);
}

TEST(ErgunWenYu, ACoefficientNoGrainCanGiveIsANumericalError) {
  EXPECT_THROW(ergun_wen_yu_grain_size({0.6, 1000.0, mu, 0.0}, 1e40), cosim::NumericalError);
  EXPECT_THROW(ergun_wen_yu_grain_size({0.6, 1000.0, mu, 0.0}, 1e-12), cosim::NumericalError);
}

TEST(ErgunWenYu, TheClampedGrainStaysInRangeForATraceOfSoil) {
  const CloudDragInput trace{2.4e-6, 1000.0, mu, 0.01};
  EXPECT_DOUBLE_EQ(ergun_wen_yu_grain_size_within_range(trace, 4.6e-7), largest_grain);
  EXPECT_DOUBLE_EQ(ergun_wen_yu_grain_size_within_range({0.6, 1000.0, mu, 0.0}, 1e40),
                   smallest_grain);
  const double d = ergun_wen_yu_grain_size_within_range({0.6, 1000.0, mu, 0.0}, 4.05e5);
  EXPECT_NEAR(d, ergun_wen_yu_grain_size({0.6, 1000.0, mu, 0.0}, 4.05e5), 1e-15);
}

}  // namespace
}  // namespace openfoam

#include "cosim/exchange/generalised_drag.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::exchange {
namespace {

constexpr double g = kStandardGravity;

DebrisMixture sandy_mixture() {
  return {.solid_fraction = 0.4, .solid_density = 2650, .fluid_density = 1000};
}

GeneralisedDragParameters linear_drag(double smoothing_speed) {
  GeneralisedDragParameters parameters;
  parameters.exponent = 1;
  parameters.reynolds_exponent = 2.4;
  parameters.partition_exponent = 1;
  parameters.grain_size = 1e-3;
  parameters.smoothing_speed = smoothing_speed;
  return parameters;
}

double coefficient(const DebrisMixture& mixture, const GeneralisedDragParameters& parameters) {
  const std::array<double, 2> at_rest{0.0, 0.0};
  return generalised_drag_coefficient(mixture, parameters, at_rest, at_rest);
}

TEST(SettlingVelocity, TendsToNineTenthsOfStokesForFineGrains) {
  const double d = 1e-6;
  const double stokes = (2650.0 - 1000.0) * g * d * d / (18 * 1e-3);
  EXPECT_NEAR(settling_velocity(d, 2650, 1000, 1e-3) / stokes, 0.9, 1e-6);
}

TEST(SettlingVelocity, TendsToTheSquareRootLawForCoarseGrains) {
  const double d = 1.0;
  const double square_root_law = std::sqrt(1.65 * g * d);
  EXPECT_NEAR(settling_velocity(d, 2650, 1000, 1e-3) / square_root_law, 1.0, 1e-4);
}

TEST(SettlingVelocity, IsZeroForGrainsThatFloat) {
  EXPECT_EQ(settling_velocity(1e-3, 900, 1000, 1e-3), 0.0);
}

TEST(GeneralisedDrag, UnconfinedGrainsFollowPudasainiAndMergili) {
  const DebrisMixture mixture = sandy_mixture();
  const GeneralisedDragParameters parameters = linear_drag(0.5);
  // alpha_c = 0.4, alpha_u = 0.6: P = 0.4 / 0.6, G = 0.6^1.4,
  // F = (1000/2650)/180 (0.6/0.4)^3 Re_p, S_p = (P/0.4 + (1-P)/0.6) 0.5
  const double u_t = settling_velocity(1e-3, 2650, 1000, 1e-3);
  const double p = 0.4 / 0.6;
  const double f = 1000.0 / 2650.0 / 180.0 * 3.375 * (1000.0 * 1e-3 * u_t / 1e-3);
  const double big_g = std::pow(0.6, 1.4);
  const double s_p = (p / 0.4 + (1 - p) / 0.6) * 0.5;
  const double expected = 0.4 * 0.6 * 1650.0 * g / (u_t * (p * f + (1 - p) * big_g) + s_p);
  EXPECT_NEAR(coefficient(mixture, parameters), expected, 1e-12 * expected);
}

TEST(GeneralisedDrag, StructuredBlocksSettleAsTheirMixedDensityWithNoFluidLikePart) {
  DebrisMixture mixture = sandy_mixture();
  mixture.structured_solid_share = 1;
  mixture.confined_fluid_share = 0.5;  // alpha_c = 0.7, alpha_u = 0.3
  EXPECT_NEAR(mixture.confined_fraction(), 0.7, 1e-15);
  EXPECT_NEAR(mixture.free_fluid_fraction(), 0.3, 1e-15);
  const double rho_c = (0.4 * 2650 + 0.3 * 1000) / 0.7;
  EXPECT_NEAR(mixture.confined_density(), rho_c, 1e-12);
  GeneralisedDragParameters parameters = linear_drag(0.0);
  parameters.block_size = 0.5;
  const double u_t = settling_velocity(0.5, rho_c, 1000, 1e-3);
  const double expected = 0.7 * 0.3 * (rho_c - 1000) * g / (u_t * std::pow(0.3, 1.4));
  EXPECT_NEAR(coefficient(mixture, parameters), expected, 1e-12 * expected);
}

TEST(GeneralisedDrag, IsZeroWithoutSolidsOrWithoutFreeFluid) {
  DebrisMixture mixture = sandy_mixture();
  mixture.solid_fraction = 0;
  EXPECT_EQ(coefficient(mixture, linear_drag(0.5)), 0.0);
  mixture.solid_fraction = 0.4;
  mixture.confined_fluid_share = 1;
  EXPECT_EQ(coefficient(mixture, linear_drag(0.5)), 0.0);
}

TEST(GeneralisedDrag, TheSmoothingSpeedIsTheMixturesVolumeWeightedSpeed) {
  const DebrisMixture mixture = sandy_mixture();
  GeneralisedDragParameters from_velocities = linear_drag(0);
  from_velocities.smoothing_speed.reset();
  const std::array<double, 2> u_c{1.0, -2.0};
  const std::array<double, 2> u_u{3.0, 1.0};
  // alpha_c u_c + alpha_u u_u = (2.2, -0.2)
  const double expected = coefficient(mixture, linear_drag(std::hypot(2.2, -0.2)));
  EXPECT_NEAR(generalised_drag_coefficient(mixture, from_velocities, u_c, u_u), expected,
              1e-13 * expected);
}

TEST(GeneralisedDrag, TheQuadraticLawDividesByTheSameSpeedOnceMore) {
  // j = 2 raises the denominator D [m s^-1] to the second power, so that
  // C_1^2 / C_2 = alpha_c alpha_u (rho_s - rho_f) g and C |w|^j is a force
  // density for either j.
  const DebrisMixture mixture = sandy_mixture();
  GeneralisedDragParameters quadratic = linear_drag(0.5);
  quadratic.exponent = 2;
  const double linear_coefficient = coefficient(mixture, linear_drag(0.5));
  const double quadratic_coefficient = coefficient(mixture, quadratic);
  EXPECT_NEAR(linear_coefficient * linear_coefficient / quadratic_coefficient,
              0.4 * 0.6 * 1650.0 * g, 1e-10 * 0.4 * 0.6 * 1650.0 * g);
}

TEST(GeneralisedDrag, GrowsAsTheFreeFluidIsSqueezedOut) {
  DebrisMixture mixture = sandy_mixture();
  double previous = 0;
  for (const double alpha_s : {0.1, 0.3, 0.5}) {
    mixture.solid_fraction = alpha_s;
    const double value = coefficient(mixture, linear_drag(0.5));
    EXPECT_GT(value, previous) << "alpha_s " << alpha_s;
    previous = value;
  }
}

TEST(VirtualMass, CoefficientIsHalfOfOnePlusTwiceTheSolidsOverTheFluid) {
  EXPECT_NEAR(virtual_mass_coefficient(sandy_mixture()), 0.5 * 1.8 / 0.6, 1e-15);
}

void expect_refused(const GeneralisedDragParameters& parameters, const std::string& what) {
  try {
    check(parameters);
    FAIL() << "accepted " << what;
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
  }
}

TEST(GeneralisedDrag, RefusesParametersOutOfTheirRange) {
  GeneralisedDragParameters parameters = linear_drag(0.5);
  EXPECT_NO_THROW(check(parameters));
  parameters.exponent = 0;
  expect_refused(parameters, "drag exponent j");
  parameters = linear_drag(0.5);
  parameters.exponent = 3;
  expect_refused(parameters, "drag exponent j");
  parameters = linear_drag(0.5);
  parameters.reynolds_exponent = 0.5;
  expect_refused(parameters, "exponent M");
  parameters = linear_drag(0.5);
  parameters.grain_size = 0;
  expect_refused(parameters, "grain size");
  parameters = linear_drag(-1);
  expect_refused(parameters, "smoothing speed");

  DebrisMixture mixture = sandy_mixture();
  EXPECT_NO_THROW(check(mixture));
  mixture.solid_fraction = 1.2;
  EXPECT_THROW(check(mixture), std::invalid_argument);
  mixture = sandy_mixture();
  mixture.solid_density = 900;
  EXPECT_THROW(check(mixture), std::invalid_argument);
  mixture = sandy_mixture();
  mixture.confined_fluid_share = std::nan("");
  EXPECT_THROW(check(mixture), std::invalid_argument);
}

TEST(GeneralisedDrag, RefusesVelocitiesOfDifferentSizes) {
  const std::array<double, 2> planar{0.0, 0.0};
  const std::array<double, 3> spatial{0.0, 0.0, 0.0};
  EXPECT_THROW(generalised_drag_coefficient(sandy_mixture(), linear_drag(0.5), planar, spatial),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosim::exchange

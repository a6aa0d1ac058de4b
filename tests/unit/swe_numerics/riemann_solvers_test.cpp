#include "swe/numerics/riemann_solvers.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace {

constexpr double g = 9.81;
constexpr std::array<swe::FluxKind, 3> all_fluxes{swe::FluxKind::roe, swe::FluxKind::hll,
                                                  swe::FluxKind::hllc};

class EveryFlux : public ::testing::TestWithParam<swe::FluxKind> {};

TEST_P(EveryFlux, IsConsistentWithThePhysicalFlux) {
  for (const swe::FaceState s : {swe::FaceState{1.0, 0.3, -0.2}, swe::FaceState{0.2, -1.5, 0.7},
                                 swe::FaceState{2.0, 6.0, 1.0}}) {
    const swe::FaceFlux f = swe::numerical_flux(GetParam(), s, s, g);
    const swe::FaceFlux exact = swe::physical_flux(s, g);
    EXPECT_NEAR(f.mass, exact.mass, 1e-14);
    EXPECT_NEAR(f.normal_momentum, exact.normal_momentum, 1e-13);
    EXPECT_NEAR(f.tangential_momentum, exact.tangential_momentum, 1e-14);
  }
}

TEST_P(EveryFlux, IsSymmetricUnderReflection) {
  // Mirroring the problem (x -> -x) swaps the sides and negates u_n: the
  // mass and tangential fluxes change sign, the normal momentum flux does not.
  const swe::FaceState l{1.0, 0.4, 0.3}, r{0.5, -0.1, -0.6};
  const swe::FaceFlux f = swe::numerical_flux(GetParam(), l, r, g);
  const swe::FaceFlux m =
      swe::numerical_flux(GetParam(), {r.h, -r.un, r.ut}, {l.h, -l.un, l.ut}, g);
  EXPECT_NEAR(f.mass, -m.mass, 1e-14);
  EXPECT_NEAR(f.normal_momentum, m.normal_momentum, 1e-14);
  EXPECT_NEAR(f.tangential_momentum, -m.tangential_momentum, 1e-14);
}

TEST_P(EveryFlux, GivesNoFluxBetweenDryStatesAndOnlyPressureAtRest) {
  const swe::FaceFlux dry = swe::numerical_flux(GetParam(), {}, {}, g);
  EXPECT_EQ(dry.mass, 0.0);
  EXPECT_EQ(dry.normal_momentum, 0.0);
  const swe::FaceFlux rest = swe::numerical_flux(GetParam(), {0.7, 0.0, 0.0}, {0.7, 0.0, 0.0}, g);
  EXPECT_EQ(rest.mass, 0.0);
  EXPECT_DOUBLE_EQ(rest.normal_momentum, 0.5 * g * 0.49);
}

TEST_P(EveryFlux, DrawsWaterOutOfAWetSideIntoADrySide) {
  // Dam break onto a dry bed: water flows right, never out of the dry side.
  const swe::FaceFlux f = swe::numerical_flux(GetParam(), {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, g);
  EXPECT_GT(f.mass, 0.0);
  const swe::FaceFlux b = swe::numerical_flux(GetParam(), {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, g);
  EXPECT_LT(b.mass, 0.0);
}

TEST_P(EveryFlux, UpwindsTheTangentialVelocityWithTheFlow) {
  const swe::FaceFlux f = swe::numerical_flux(GetParam(), {1.0, 0.5, 2.0}, {1.0, 0.5, -3.0}, g);
  EXPECT_NEAR(f.tangential_momentum, f.mass * 2.0, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Swe, EveryFlux, ::testing::ValuesIn(all_fluxes),
                         [](const auto& p) { return std::string(swe::to_string(p.param)); });

TEST(RoeFlux, MatchesTheExactStokerStateOnAStationaryShock) {
  // A stationary hydraulic jump (Rankine-Hugoniot with shock speed 0) is an
  // exact discrete solution of Roe's scheme: the flux equals F(U_l) = F(U_r).
  const double h1 = 1.0, h2 = 2.0;
  const double u1 =
      std::sqrt(0.5 * g * h2 * (h1 + h2) / h1);  // h1 u1 = h2 u2, momentum flux continuous
  const double u2 = h1 * u1 / h2;
  const swe::FaceFlux f = swe::roe_flux({h1, u1, 0.0}, {h2, u2, 0.0}, g);
  const swe::FaceFlux left = swe::physical_flux({h1, u1, 0.0}, g);
  EXPECT_NEAR(f.mass, left.mass, 1e-12);
  EXPECT_NEAR(f.normal_momentum, left.normal_momentum, 1e-12);
}

}  // namespace

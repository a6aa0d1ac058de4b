// The branch-free fluxes and slopes of the 1D block kernels against the
// shared swe/numerics solvers and limiter on random states, dry sides
// included.
#include "solver_1d/branch_free_flux.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "solver_1d/branch_free_slope.hpp"
#include "swe/numerics/riemann_solvers.hpp"
#include "swe/numerics/slope_limiter.hpp"

namespace {

constexpr double g = 9.81;
constexpr double relative_tolerance = 1e-14;

double relative_difference(double value, double reference) {
  return std::abs(value - reference) / std::max(1.0, std::abs(reference));
}

// Depths: wet, tiny or exactly dry on either side, both dry now and then.
struct RandomFaces {
  std::mt19937_64 rng{20240611};
  std::uniform_real_distribution<double> depth{0.0, 3.0}, velocity{-6.0, 6.0};
  std::uniform_int_distribution<int> kind{0, 9};
  double random_depth() {
    const int k = kind(rng);
    if (k == 0) return 0.0;
    if (k == 1) return 1e-9 * depth(rng);
    return depth(rng);
  }
};

template <swe::FluxKind flux>
void expect_same_fluxes(swe::FaceFlux (*reference)(const swe::FaceState&, const swe::FaceState&,
                                                   double)) {
  RandomFaces faces;
  double worst = 0.0;
  int dry_faces = 0;
  for (int i = 0; i < 200000; ++i) {
    const double hl = faces.random_depth(), hr = faces.random_depth();
    const double ul = hl > 0.0 ? faces.velocity(faces.rng) : 0.0;
    const double ur = hr > 0.0 ? faces.velocity(faces.rng) : 0.0;
    if (hl <= 0.0 || hr <= 0.0) ++dry_faces;
    const swe::FaceFlux expected = reference({hl, ul, 0.0}, {hr, ur, 0.0}, g);
    const swe::solver_1d::FaceFlux1d f =
        swe::solver_1d::face_flux_1d<flux>(hl, ul, hr, ur, g, std::sqrt(g));
    worst = std::max({worst, relative_difference(f.mass, expected.mass),
                      relative_difference(f.momentum, expected.normal_momentum)});
    ASSERT_LE(relative_difference(f.mass, expected.mass), relative_tolerance)
        << "hl " << hl << " ul " << ul << " hr " << hr << " ur " << ur;
    ASSERT_LE(relative_difference(f.momentum, expected.normal_momentum), relative_tolerance)
        << "hl " << hl << " ul " << ul << " hr " << hr << " ur " << ur;
  }
  EXPECT_GT(dry_faces, 10000);
  std::cout << swe::to_string(flux) << ": largest relative difference " << worst << " (tolerance "
            << relative_tolerance << ") over 200000 faces, " << dry_faces << " with a dry side\n";
}

TEST(BranchFreeFlux, HllMatchesSharedSolver) {
  expect_same_fluxes<swe::FluxKind::hll>(&swe::hll_flux);
}

TEST(BranchFreeFlux, HllcMatchesSharedSolverIn1d) {
  expect_same_fluxes<swe::FluxKind::hllc>(&swe::hllc_flux);
}

TEST(BranchFreeFlux, RoeMatchesSharedSolver) {
  expect_same_fluxes<swe::FluxKind::roe>(&swe::roe_flux);
}

// Where it reports itself plain, the plain Roe formula is the whole of
// swe::roe_flux; it must not claim so at a dry side.
TEST(BranchFreeFlux, PlainRoeMatchesSharedSolverWhereItClaimsTo) {
  RandomFaces faces;
  int plain_faces = 0, other_faces = 0;
  for (int i = 0; i < 200000; ++i) {
    const double hl = faces.random_depth(), hr = faces.random_depth();
    const double ul = faces.velocity(faces.rng), ur = faces.velocity(faces.rng);
    const swe::solver_1d::PlainRoeFlux1d f =
        swe::solver_1d::plain_roe_flux_1d(hl, ul, hr, ur, g, std::sqrt(g));
    if (hl <= 0.0 || hr <= 0.0) {
      ASSERT_EQ(f.plain, 0.0) << "hl " << hl << " hr " << hr;
    }
    if (f.plain == 0.0) {
      ++other_faces;
      continue;
    }
    ++plain_faces;
    const swe::FaceFlux expected = swe::roe_flux({hl, ul, 0.0}, {hr, ur, 0.0}, g);
    ASSERT_LE(relative_difference(f.mass, expected.mass), relative_tolerance)
        << "hl " << hl << " ul " << ul << " hr " << hr << " ur " << ur;
    ASSERT_LE(relative_difference(f.momentum, expected.normal_momentum), relative_tolerance)
        << "hl " << hl << " ul " << ul << " hr " << hr << " ur " << ur;
  }
  EXPECT_GT(plain_faces, 100000);
  EXPECT_GT(other_faces, 10000);
}

template <swe::LimiterKind limiter>
void expect_same_slopes() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> difference(-2.0, 2.0);
  std::uniform_int_distribution<int> zero(0, 7);
  for (int i = 0; i < 100000; ++i) {
    const double a = zero(rng) == 0 ? 0.0 : difference(rng);
    const double b = zero(rng) == 0 ? 0.0 : difference(rng);
    const double expected = swe::limited_slope(limiter, a, b);
    ASSERT_LE(relative_difference(swe::limited_slope<limiter>(a, b), expected), relative_tolerance)
        << swe::to_string(limiter) << " a " << a << " b " << b;
  }
}

TEST(BranchFreeSlope, MatchesSharedLimiters) {
  expect_same_slopes<swe::LimiterKind::none>();
  expect_same_slopes<swe::LimiterKind::minmod>();
  expect_same_slopes<swe::LimiterKind::van_leer>();
  expect_same_slopes<swe::LimiterKind::monotonized_central>();
}

}  // namespace

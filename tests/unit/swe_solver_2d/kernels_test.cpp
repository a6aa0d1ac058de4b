// The solver's vectorisable kernels against the shared numerics: the same
// bits on wet, dry, sub- and supercritical faces and on every slope sign.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "solver_2d/directional_sweep.hpp"
#include "solver_2d/hllc_selects.hpp"
#include "swe/numerics/riemann_solvers.hpp"
#include "swe/numerics/slope_limiter.hpp"

namespace {

std::vector<swe::FaceState> states() {
  std::vector<swe::FaceState> s = {{0.0, 0.0, 0.0},  {0.0, 1.0, 0.5},  {1.0, 0.0, 0.0},
                                   {0.5, 3.0, -1.0}, {0.5, -3.0, 1.0}, {2.0, 10.0, 0.2},
                                   {0.1, -8.0, 0.0}, {1e-9, 0.0, 0.0}};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> depth(0.0, 2.0), speed(-6.0, 6.0);
  for (int k = 0; k < 200; ++k) s.push_back({depth(random), speed(random), speed(random)});
  return s;
}

TEST(Solver2dKernels, HllcWithSelectsGivesTheBitsOfHllcFlux) {
  const auto all = states();
  int differences = 0, compared = 0;
  for (const auto& l : all) {
    for (const auto& r : all) {
      const swe::FaceFlux a = swe::hllc_flux(l, r, 9.81);
      const swe::FaceFlux b = swe::solver_2d::hllc_flux_selects(l, r, 9.81);
      differences += a.mass != b.mass || a.normal_momentum != b.normal_momentum ||
                     a.tangential_momentum != b.tangential_momentum;
      ++compared;
    }
  }
  EXPECT_EQ(differences, 0) << "of " << compared;
}

TEST(Solver2dKernels, BranchFreeSlopesGiveTheBitsOfLimitedSlope) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jump(-1.0, 1.0);
  std::vector<std::pair<double, double>> pairs = {
      {0.0, 0.0}, {1.0, -1.0}, {0.0, 1.0}, {0.3, 0.3}, {-0.2, -0.7}};
  for (int k = 0; k < 2000; ++k) pairs.emplace_back(jump(random), jump(random));
  int differences = 0;
  for (const auto& [a, b] : pairs) {
    using swe::LimiterKind;
    differences +=
        swe::limited_slope<LimiterKind::none>(a, b) != swe::limited_slope(LimiterKind::none, a, b);
    differences += swe::limited_slope<LimiterKind::minmod>(a, b) !=
                   swe::limited_slope(LimiterKind::minmod, a, b);
    differences += swe::limited_slope<LimiterKind::van_leer>(a, b) !=
                   swe::limited_slope(LimiterKind::van_leer, a, b);
    differences += swe::limited_slope<LimiterKind::monotonized_central>(a, b) !=
                   swe::limited_slope(LimiterKind::monotonized_central, a, b);
  }
  EXPECT_EQ(differences, 0);
}

}  // namespace

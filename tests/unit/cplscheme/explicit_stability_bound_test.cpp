#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cplscheme/explicit_stability.hpp"

namespace cosim::cplscheme {
namespace {

// Saturated sand in water: K_f = 2.2 GPa, n = 0.4, rho_bar_f = n 1000,
// rho_bar_s = (1 - n) 2650: c = sqrt(K_f / (n (400 + 1590))) = 1662.5 m/s;
// across 0.1 m cells the bound is 0.1 / c = 60.1 us.
TEST(ExplicitStability, TheUndrainedWaveAcrossTheNarrowestCellBoundsTheWindow) {
  const Mesh grid{"g", UniformGrid{2, {0, 0, 0}, {0.2, 0.1, 1}, {4, 3, 1}}};
  const std::size_t cells = grid.size();
  std::vector<double> phi_s(cells, 0.6), rho_s(cells, 1590.0), rho_f(cells, 400.0),
      modulus(cells, 2.2e9);
  const auto bound = undrained_wave_bound(grid, phi_s, rho_s, rho_f, modulus);
  const double c = std::sqrt(2.2e9 / (0.4 * 1990.0));
  EXPECT_NEAR(bound.wave_speed, c, 1e-9 * c);
  EXPECT_NEAR(bound.window, 0.1 / c, 1e-15);
  EXPECT_DOUBLE_EQ(bound.cell_width, 0.1);
  EXPECT_TRUE(bound.applies());
}

// The limiting cell is the fastest: the one with the fewest pores.
TEST(ExplicitStability, TheCellWithTheFastestWaveLimits) {
  const Mesh line{"l", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {5, 1, 1}}};
  std::vector<double> phi_s{0.3, 0.6, 0.9, 0.5, 0.2}, rho_s(5, 1500.0), rho_f(5, 500.0),
      modulus(5, 2.2e9);
  EXPECT_EQ(undrained_wave_bound(line, phi_s, rho_s, rho_f, modulus).cell, 2u);
}

// Pure fluid, full solid and held solids carry no undrained wave: no bound.
TEST(ExplicitStability, CellsWithoutSolidWithoutPoresOrHeldGiveNoBound) {
  const Mesh line{"l", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {3, 1, 1}}};
  std::vector<double> phi_s{0.0, 1.0, 0.5}, rho_s{0.0, 2650.0, 1e25}, rho_f(3, 1000.0),
      modulus(3, 2.2e9);
  EXPECT_FALSE(undrained_wave_bound(line, phi_s, rho_s, rho_f, modulus).applies());
}

}  // namespace
}  // namespace cosim::cplscheme

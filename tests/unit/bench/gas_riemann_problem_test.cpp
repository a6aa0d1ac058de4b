#include "bench/gas_riemann_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace cosim::bench {
namespace {

struct ToroTest {
  GasState left, right;
  double star_pressure, star_velocity;
};

// Toro, Riemann Solvers, Tables 4.1-4.3 (gamma = 1.4), printed to 5-6 digits.
TEST(ExactRiemann, MatchesToroTable43) {
  const ToroTest tests[] = {
      {{1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 0.30313, 0.92745},
      {{1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 0.00189, 0.0},
      {{1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 460.894, 19.5975},
      {{1.0, 0.0, 0.01}, {1.0, 0.0, 100.0}, 46.0950, -6.19633},
      {{5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 1691.64, 8.68975},
  };
  for (const ToroTest& test : tests) {
    const ExactRiemannSolution s(test.left, test.right, 1.4);
    EXPECT_NEAR(s.star_pressure(), test.star_pressure, 6e-6 * test.star_pressure + 6e-6);
    EXPECT_NEAR(s.star_velocity(), test.star_velocity, 6e-6 * std::abs(test.star_velocity) + 1e-5);
  }
}

TEST(ExactRiemann, SodStarDensities) {
  const ExactRiemannSolution s({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  // Behind the rarefaction and behind the shock (Toro section 4.3.3).
  EXPECT_NEAR(s.sample(s.star_velocity() - 1e-9).density, 0.42632, 1e-5);
  EXPECT_NEAR(s.sample(s.star_velocity() + 1e-9).density, 0.26557, 1e-5);
  EXPECT_DOUBLE_EQ(s.sample(-10.0).density, 1.0);
  EXPECT_DOUBLE_EQ(s.sample(10.0).density, 0.125);
  // The fan is continuous at its head and tail.
  const double head = -std::sqrt(1.4);
  EXPECT_NEAR(s.sample(head + 1e-9).density, 1.0, 1e-8);
}

TEST(ExactRiemann, CellAveragesConserveMass) {
  const ExactRiemannSolution s({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const auto cells = cell_averages(s, 1.4, 0.0, 1.0, 100, 0.5, 0.2);
  double mass = 0.0;
  for (const GasState& c : cells) mass += c.density * 0.01;
  EXPECT_NEAR(mass, 0.5 * 1.0 + 0.5 * 0.125, 1e-4);
  EXPECT_DOUBLE_EQ(cells.front().density, 1.0);
  EXPECT_DOUBLE_EQ(cells.back().pressure, 0.1);
}

TEST(ExactRiemann, RefusesVacuumAndBadStates) {
  EXPECT_THROW(ExactRiemannSolution({1.0, -20.0, 0.4}, {1.0, 20.0, 0.4}, 1.4),
               std::invalid_argument);
  EXPECT_THROW(ExactRiemannSolution({0.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, 1.4), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::bench

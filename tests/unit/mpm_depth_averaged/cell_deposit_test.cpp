#include "mpm/depth_averaged/cell_deposit.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

namespace mpm {
namespace {

cosim::UniformGrid cells(int nx, int ny, double dx) {
  GridGeometry<2> grid;
  grid.origin = Vec<2>{-1.0, 2.0};
  grid.spacing = Vec<2>::Constant(dx);
  grid.cells = {nx, ny};
  return ground_cells(grid);
}

std::vector<Vec<2>> scattered(std::size_t n, const Vec<2>& lower, const Vec<2>& upper) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<2>> x(n);
  for (auto& p : x)
    p = {lower[0] + u(random) * (upper[0] - lower[0]),
         lower[1] + u(random) * (upper[1] - lower[1])};
  return x;
}

TEST(CellDeposit, SharesArePositiveAndSumToOneUpToTheGridsEdges) {
  const CellDeposit deposit(cells(5, 4, 0.5));
  for (const Vec<2>& x : scattered(500, {-1.0, 2.0}, {1.5, 4.0})) {
    double sum = 0.0;
    deposit.for_each_share(x, [&](std::size_t c, double share) {
      EXPECT_LT(c, 20u);
      EXPECT_GE(share, 0.0);
      sum += share;
    });
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
  // At a cell's centre the point is all that cell's.
  deposit.for_each_share({0.25, 2.75}, [](std::size_t c, double share) {
    EXPECT_EQ(share, c == 1 * 5 + 2 ? 1.0 : 0.0);
  });
}

TEST(CellDeposit, ConservesEveryComponentBothWays) {
  const CellDeposit deposit(cells(12, 9, 0.25));
  const auto x = scattered(300, {-0.9, 2.1}, {0.5, 3.0});  // the mass covers part of the grid
  std::vector<double> mass(x.size()), momentum(2 * x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    mass[p] = 1.0 + 0.01 * static_cast<double>(p);
    momentum[2 * p] = mass[p] * 3.0;
    momentum[2 * p + 1] = -mass[p] * static_cast<double>(p % 7);
  }
  const auto on_cells = deposit.deposit(x, momentum, 2);
  for (int k = 0; k < 2; ++k) {
    double points = 0.0, grid = 0.0;
    for (std::size_t p = 0; p < x.size(); ++p)
      points += momentum[2 * p + static_cast<std::size_t>(k)];
    for (std::size_t c = 0; c < 108; ++c) grid += on_cells[2 * c + static_cast<std::size_t>(k)];
    EXPECT_NEAR(grid, points, 1e-13 * std::abs(points));
  }
  // An impulse on every cell, also on cells the points do not reach: it
  // goes whole to the points.
  std::vector<double> impulse(2 * 108);
  for (std::size_t i = 0; i < impulse.size(); ++i) impulse[i] = std::sin(static_cast<double>(i));
  std::vector<double> unplaced;
  const auto to_points = deposit.distribute(x, mass, impulse, 2, &unplaced);
  for (std::size_t k = 0; k < 2; ++k) {
    double sent = 0.0, received = 0.0;
    for (std::size_t c = 0; c < 108; ++c) sent += impulse[2 * c + k];
    for (std::size_t p = 0; p < x.size(); ++p) received += to_points[2 * p + k];
    EXPECT_NEAR(received, sent, 1e-13 * 108);
    EXPECT_EQ(unplaced[k], 0.0);
  }
}

TEST(CellDeposit, AUniformImpulsePerMassGivesEveryPointTheSameVelocityChange) {
  const CellDeposit deposit(cells(6, 6, 1.0));
  const auto x = scattered(200, {-1.0, 2.0}, {5.0, 8.0});
  const std::vector<double> mass(x.size(), 2.0);
  const auto cell_mass = deposit.deposit(x, mass, 1);
  std::vector<double> impulse(2 * 36);
  for (std::size_t c = 0; c < 36; ++c) {
    impulse[2 * c] = 0.5 * cell_mass[c];
    impulse[2 * c + 1] = -cell_mass[c];
  }
  const auto to_points = deposit.distribute(x, mass, impulse, 2, nullptr);
  for (std::size_t p = 0; p < x.size(); ++p) {
    EXPECT_NEAR(to_points[2 * p] / mass[p], 0.5, 1e-12);
    EXPECT_NEAR(to_points[2 * p + 1] / mass[p], -1.0, 1e-12);
  }
}

TEST(CellDeposit, SaysWhatNoPointCouldTake) {
  const CellDeposit deposit(cells(3, 3, 1.0));
  std::vector<double> unplaced;
  const auto none = deposit.distribute({}, {}, std::vector<double>(9, 1.5), 1, &unplaced);
  EXPECT_TRUE(none.empty());
  EXPECT_DOUBLE_EQ(unplaced[0], 13.5);
  EXPECT_THROW(CellDeposit(cells(1, 3, 1.0)), std::invalid_argument);
  EXPECT_THROW((void)deposit.deposit(std::vector<Vec<2>>(2), std::vector<double>(3), 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace mpm

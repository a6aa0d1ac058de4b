#include "swe/coupling/extended_free_surface.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "swe/solver_2d.hpp"

namespace {

// A 6 x 3 basin whose ground rises to the right: water in the three left
// columns only.
std::unique_ptr<swe::Solver2d> basin(double level) {
  swe::Grid2d grid;
  grid.cells = {6, 3};
  grid.spacing = {1.0, 1.0};
  auto s =
      std::make_unique<swe::Solver2d>(grid, swe::Physics{}, swe::Scheme{}, swe::Boundaries2d{});
  std::vector<double> bed(18), h(18, 0.0);
  for (std::size_t c = 0; c < 18; ++c) {
    bed[c] = 0.5 * static_cast<double>(c % 6);  // 0, 0.5, ..., 2.5
    h[c] = std::max(0.0, level - bed[c]);
  }
  s->set_bed(bed);
  s->set_state(h, std::vector<double>(18, 0.0), std::vector<double>(18, 0.0));
  return s;
}

TEST(ExtendedFreeSurface, IsTheWaterLevelOnWetCellsAndTheNearestWatersOverDryOnes) {
  const auto s = basin(1.2);  // wet where the bed is below 1.2: columns 0-2
  const std::vector<double> dry(18, -100.0);
  const auto eta = swe::extended_free_surface(*s, dry);
  ASSERT_EQ(eta.size(), 18u);
  // A lake at rest: one level everywhere, carried over the dry slope.
  for (std::size_t c = 0; c < 18; ++c) EXPECT_NEAR(eta[c], 1.2, 1e-12) << "cell " << c;
}

TEST(ExtendedFreeSurface, AveragesTheNeighboursReachedFirst) {
  swe::Grid2d grid;
  grid.cells = {3, 2};
  swe::Solver2d s(grid, swe::Physics{}, swe::Scheme{}, {});
  // Two wet cells at different levels (a moving surface), the rest dry.
  std::vector<double> h{1.0, 0.0, 3.0, 0.0, 0.0, 0.0};
  s.set_state(h, std::vector<double>(6, 0.0), std::vector<double>(6, 0.0));
  const auto eta = swe::extended_free_surface(s, std::vector<double>(6, 0.0));
  EXPECT_DOUBLE_EQ(eta[0], 1.0);
  EXPECT_DOUBLE_EQ(eta[2], 3.0);
  EXPECT_DOUBLE_EQ(eta[1], 2.0);  // between both, reached in the first ring
  EXPECT_DOUBLE_EQ(eta[3], 1.0);
  EXPECT_DOUBLE_EQ(eta[5], 3.0);
  EXPECT_DOUBLE_EQ(eta[4], 2.0);  // from cell 1 (2.0) and cells 3, 5 (1.0, 3.0) of ring one
}

TEST(ExtendedFreeSurface, IsTheDryLevelWithoutWater) {
  const auto s = basin(-1.0);
  std::vector<double> dry(18);
  for (std::size_t c = 0; c < 18; ++c) dry[c] = 0.1 * static_cast<double>(c);
  EXPECT_EQ(swe::extended_free_surface(*s, dry), dry);
  EXPECT_THROW((void)swe::extended_free_surface(*s, std::vector<double>(3, 0.0)),
               std::invalid_argument);
}

}  // namespace

#include "cosim/decomposition/balanced_cuts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace cosim::decomposition {
namespace {

TEST(BalancedCuts, SplitsAnEvenLoadEvenly) {
  const std::vector<double> even(12, 5.0);
  EXPECT_EQ(balanced_cuts(even, 4), (std::vector<std::int64_t>{0, 3, 6, 9, 12}));
  EXPECT_DOUBLE_EQ(imbalance(even, balanced_cuts(even, 4)), 1.0);
  // Without weight, by slabs.
  const std::vector<double> none(10, 0.0);
  EXPECT_EQ(balanced_cuts(none, 2), (std::vector<std::int64_t>{0, 5, 10}));
  EXPECT_EQ(imbalance(none, balanced_cuts(none, 2)), 0.0);
}

TEST(BalancedCuts, MovesTheCutsToWhereTheParticlesAre) {
  // A heap of particles over slabs 20-39 of 100: even cuts by slabs would
  // give two of four parts nearly all of them.
  std::vector<double> heap(100, 1.0);
  for (std::size_t i = 20; i < 40; ++i) heap[i] = 200.0 + 10.0 * std::sin(static_cast<double>(i));
  const auto cuts = balanced_cuts(heap, 4);
  const std::vector<std::int64_t> by_slabs{0, 25, 50, 75, 100};
  EXPECT_LT(imbalance(heap, cuts), 1.1);
  EXPECT_GT(imbalance(heap, by_slabs), 2.5);
  for (std::size_t p = 1; p < 4; ++p) EXPECT_LE(cuts[p], 40);  // three cuts inside the heap
}

TEST(BalancedCuts, KeepsEachPartItsMinimumOfSlabs) {
  std::vector<double> spike(10, 0.0);
  spike[0] = 100.0;  // all the weight in the first slab
  const auto cuts = balanced_cuts(spike, 3, 2);
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) EXPECT_GE(cuts[p + 1] - cuts[p], 2);
  EXPECT_EQ(cuts.front(), 0);
  EXPECT_EQ(cuts.back(), 10);
}

TEST(BalancedCuts, RefusesWhatCannotBeSplit) {
  const std::vector<double> few(5, 1.0);
  EXPECT_THROW((void)balanced_cuts(few, 3, 2), std::invalid_argument);
  EXPECT_THROW((void)balanced_cuts(few, 0), std::invalid_argument);
  std::vector<double> bad(5, 1.0);
  bad[2] = -1.0;
  EXPECT_THROW((void)balanced_cuts(bad, 2), std::invalid_argument);
  bad[2] = std::nan("");
  EXPECT_THROW((void)balanced_cuts(bad, 2), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::decomposition

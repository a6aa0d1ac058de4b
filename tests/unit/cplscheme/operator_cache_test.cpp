#include "cplscheme/operator_cache.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosim::cplscheme {
namespace {

const Mesh fine{"cells", UniformGrid{1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1}}};
const Mesh coarse{"grid", UniformGrid{1, {0, 0, 0}, {0.2, 1, 1}, {5, 1, 1}}};

OperatorKey fluid_to_soil(mapping::Constraint constraint) {
  return {{"fluid", "cells"}, {"soil", "grid"}, constraint, mapping::Kernel::linear};
}

// A field exchanged on a mesh pair and the same pair mapped by an exchange
// step share one operator.
TEST(OperatorCache, OneOperatorPerMeshPairConstraintAndKernel) {
  OperatorCache cache;
  const auto consistent = fluid_to_soil(mapping::Constraint::consistent);
  const mapping::Operator& first = cache.get(consistent, fine, 1, coarse, 1);
  const mapping::Operator& second = cache.get(consistent, fine, 1, coarse, 1);
  EXPECT_EQ(&first, &second);
  EXPECT_EQ(cache.builds(), 1u);
  cache.get(fluid_to_soil(mapping::Constraint::conservative), fine, 1, coarse, 1);
  EXPECT_EQ(cache.builds(), 2u);
  OperatorKey quadratic = consistent;
  quadratic.kernel = mapping::Kernel::quadratic_bspline;
  cache.get(quadratic, fine, 1, coarse, 1);
  EXPECT_EQ(cache.builds(), 3u);
  cache.get({{"fluid", "cells"}, {"solid", "grid"}, consistent.constraint, consistent.kernel}, fine,
            1, coarse, 1);
  EXPECT_EQ(cache.builds(), 4u);
}

TEST(OperatorCache, ANewMeshVersionRebuildsTheOperator) {
  OperatorCache cache;
  const auto key = fluid_to_soil(mapping::Constraint::consistent);
  const std::vector<double> ones(fine.size(), 1.0);
  const std::vector<double> before = cache.get(key, fine, 1, coarse, 1).apply(ones);
  cache.get(key, fine, 2, coarse, 1);
  EXPECT_EQ(cache.builds(), 2u);
  cache.get(key, fine, 2, coarse, 3);
  EXPECT_EQ(cache.builds(), 3u);
  EXPECT_EQ(cache.get(key, fine, 2, coarse, 3).apply(ones), before);
  EXPECT_EQ(cache.builds(), 3u);
}

}  // namespace
}  // namespace cosim::cplscheme

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "mapping/build_operator.hpp"
#include "mapping_test_support.hpp"

namespace cosim::mapping {
namespace {

using testing::max_column_sum_error;
using testing::max_row_sum_error;
using testing::random_grid;
using testing::random_values;
using testing::relative_difference;
using testing::sum;

constexpr GridLocation kLocations[] = {GridLocation::cell, GridLocation::node};

TEST(OverlapMap, ConservativeGridToGridKeepsTheTotalForRandomGeometries) {
  std::mt19937_64 rng(20240611);
  for (int dim = 1; dim <= 3; ++dim) {
    double worst = 0.0;
    double worst_column = 0.0;
    for (int trial = 0; trial < 40; ++trial) {
      const std::int64_t max_cells = dim == 3 ? 9 : 25;
      const Mesh a{"a", random_grid(dim, kLocations[trial % 2], rng, 0.3, max_cells)};
      const Mesh b{"b", random_grid(dim, kLocations[(trial / 2) % 2], rng, 0.3, max_cells)};
      const Operator op = build_operator(a, b, Constraint::conservative);
      const std::vector<double> amount = random_values(a.size(), rng);
      const std::vector<double> mapped = op.apply(amount);
      worst = std::max(worst, relative_difference(sum(amount), sum(mapped)));
      worst_column = std::max(worst_column, max_column_sum_error(op.weights()));
    }
    std::printf("%dD conservative grid->grid: max relative total error %.3e, column sums %.3e\n",
                dim, worst, worst_column);
    EXPECT_LE(worst, 1e-12);
    EXPECT_LE(worst_column, 1e-12);
  }
}

TEST(OverlapMap, ConservativeRoundTripKeepsTheTotal) {
  std::mt19937_64 rng(7);
  double worst = 0.0;
  for (int dim = 1; dim <= 3; ++dim)
    for (int trial = 0; trial < 20; ++trial) {
      const Mesh a{"a", random_grid(dim, kLocations[trial % 2], rng, 0.3, dim == 3 ? 8 : 30)};
      const Mesh b{"b", random_grid(dim, kLocations[(trial + 1) % 2], rng, 0.3, dim == 3 ? 8 : 30)};
      const std::vector<double> amount = random_values(a.size(), rng);
      const auto there = build_operator(a, b, Constraint::conservative).apply(amount);
      const auto back = build_operator(b, a, Constraint::conservative).apply(there);
      worst = std::max(worst, relative_difference(sum(amount), sum(back)));
    }
  std::printf("conservative A->B->A: max relative total change %.3e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST(OverlapMap, ConsistentGridToGridReproducesAConstantExactly) {
  std::mt19937_64 rng(11);
  double worst_row = 0.0;
  double worst_value = 0.0;
  for (int dim = 1; dim <= 3; ++dim)
    for (int trial = 0; trial < 30; ++trial) {
      const Mesh a{"a", random_grid(dim, kLocations[trial % 2], rng, 0.3, dim == 3 ? 9 : 25)};
      const Mesh b{"b", random_grid(dim, kLocations[(trial / 2) % 2], rng, 0.3, dim == 3 ? 9 : 25)};
      const Operator op = build_operator(a, b, Constraint::consistent);
      const std::vector<double> constant(a.size(), 3.25);
      const auto mapped = op.apply(constant);
      std::vector<bool> empty(b.size(), false);
      for (const std::size_t t : op.empty_target_indices()) empty[t] = true;
      for (std::size_t t = 0; t < b.size(); ++t)
        worst_value = std::max(worst_value, std::abs(mapped[t] - (empty[t] ? 0.0 : 3.25)));
      worst_row = std::max(worst_row, max_row_sum_error(op.weights()));
    }
  std::printf("consistent grid->grid: max |constant error| %.3e, row sums %.3e\n", worst_value,
              worst_row);
  EXPECT_LE(worst_value, 1e-14);
  EXPECT_LE(worst_row, 1e-14);
}

double linear_field(const Vec3& x) {
  return 1.5 + 2.0 * x[0] - 0.75 * x[1] + 0.5 * x[2];
}

TEST(OverlapMap, ConsistentFineToAlignedCoarseReproducesALinearField) {
  // Each coarse cell is the union of 3^dim fine cells: the average of a linear
  // field over them is its value at the coarse centre.
  double worst = 0.0;
  for (int dim = 1; dim <= 3; ++dim) {
    const UniformGrid coarse{
        dim, {0.2, -0.1, 0.3}, {0.3, 0.15, 0.6}, {4, 5, 3}, GridLocation::cell};
    UniformGrid fine = coarse;
    for (std::size_t d = 0; d < 3; ++d) {
      fine.spacing[d] /= 3.0;
      fine.cells[d] *= 3;
    }
    const Mesh from{"fine", fine};
    const Mesh to{"coarse", coarse};
    std::vector<double> f(from.size());
    for (std::size_t e = 0; e < f.size(); ++e) f[e] = linear_field(from.position(e));
    const auto mapped = build_operator(from, to, Constraint::consistent).apply(f);
    for (std::size_t e = 0; e < mapped.size(); ++e)
      worst = std::max(worst, std::abs(mapped[e] - linear_field(to.position(e))));
  }
  std::printf("consistent fine->aligned coarse, linear field: max error %.3e\n", worst);
  EXPECT_LE(worst, 1e-13);
}

TEST(OverlapMap, ConsistentLinearFieldErrorIsFirstOrderForArbitraryOffsets) {
  const UniformGrid a{2, {0.013, -0.021, 0}, {0.05, 0.05, 1}, {40, 40, 1}, GridLocation::cell};
  const UniformGrid b{2, {0.1, 0.1, 0}, {0.037, 0.041, 1}, {20, 20, 1}, GridLocation::node};
  const Mesh from{"a", a};
  const Mesh to{"b", b};
  std::vector<double> f(from.size());
  for (std::size_t e = 0; e < f.size(); ++e) f[e] = linear_field(from.position(e));
  const auto mapped = build_operator(from, to, Constraint::consistent).apply(f);
  double worst = 0.0;
  for (std::size_t e = 0; e < mapped.size(); ++e)
    worst = std::max(worst, std::abs(mapped[e] - linear_field(to.position(e))));
  std::printf("consistent offset grids, linear field: max error %.3e (bound |grad| h = %.3e)\n",
              worst, 2.75 * 0.05);
  EXPECT_LE(worst, 2.75 * 0.05);
}

TEST(OverlapMap, ConservativeIsTheTransposeOfTheReverseConsistentMap) {
  std::mt19937_64 rng(3);
  for (int dim = 1; dim <= 3; ++dim) {
    // b covers a, so no source element needs the nearest-element fallback
    UniformGrid ga = random_grid(dim, GridLocation::cell, rng, 0.1, 7);
    UniformGrid gb = random_grid(dim, GridLocation::node, rng, 0.1, 7);
    for (std::size_t d = 0; d < 3; ++d) {
      gb.origin[d] = ga.origin[d] - 0.3;
      gb.spacing[d] = (ga.spacing[d] * static_cast<double>(ga.cells[d]) + 0.6) /
                      static_cast<double>(gb.cells[d]);
    }
    const Mesh a{"a", ga};
    const Mesh b{"b", gb};
    const Operator conservative = build_operator(a, b, Constraint::conservative);
    const Operator consistent = build_operator(b, a, Constraint::consistent);
    EXPECT_EQ(conservative.fallback_source_count(), 0u);
    const Weights difference = conservative.weights() - Weights(consistent.weights().transpose());
    const double norm = difference.norm();
    std::printf("%dD ||conservative(a->b) - consistent(b->a)^T|| = %.3e\n", dim, norm);
    EXPECT_LE(norm, 1e-14);
  }
}

TEST(OverlapMap, SourceOutsideTheTargetGoesToTheNearestElement) {
  const Mesh a{"a", UniformGrid{2, {0, 0, 0}, {1, 1, 1}, {6, 4, 1}, GridLocation::cell}};
  const Mesh b{"b", UniformGrid{2, {1.5, 1.0, 0}, {1, 1, 1}, {2, 2, 1}, GridLocation::cell}};
  const Operator op = build_operator(a, b, Constraint::conservative);
  // a's cells overlap b in x for i = 1..3 and in y for j = 1..2: 3 x 2 of 24 do
  EXPECT_EQ(op.fallback_source_count(), 24u - 6u);
  std::vector<double> amount(a.size(), 0.0);
  amount[a.size() - 1] = 5.0;  // far corner (5.5, 3.5) → nearest b cell (1, 1)
  const auto mapped = op.apply(amount);
  EXPECT_DOUBLE_EQ(mapped[3], 5.0);
  const auto all = op.apply(std::vector<double>(a.size(), 1.0));
  std::printf("fallback: total %.17g of 24\n", sum(all));
  EXPECT_NEAR(sum(all), 24.0, 1e-12);

  const Operator average = build_operator(b, a, Constraint::consistent);
  EXPECT_EQ(average.empty_target_count(), 24u - 6u);
}

TEST(OverlapMap, NonUniformLineAndUniformGridBothWays) {
  std::mt19937_64 rng(5);
  double worst_total = 0.0;
  double worst_constant = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    std::uniform_real_distribution<double> width(0.01, 0.2);
    NonUniformLine line;
    line.edges.push_back(width(rng) - 0.1);
    for (int i = 0; i < 30; ++i) line.edges.push_back(line.edges.back() + width(rng));
    const Mesh l{"line", line};
    const Mesh g{"grid", testing::random_grid(1, kLocations[trial % 2], rng, 0.3, 40)};
    for (const auto& [from, to] : {std::pair{&l, &g}, std::pair{&g, &l}}) {
      const auto amount = random_values(from->size(), rng);
      const auto mapped = build_operator(*from, *to, Constraint::conservative).apply(amount);
      worst_total = std::max(worst_total, relative_difference(sum(amount), sum(mapped)));
      const Operator avg = build_operator(*from, *to, Constraint::consistent);
      const auto constant = avg.apply(std::vector<double>(from->size(), -1.5));
      for (std::size_t t = 0; t < constant.size(); ++t)
        if (std::find(avg.empty_target_indices().begin(), avg.empty_target_indices().end(), t) ==
            avg.empty_target_indices().end())
          worst_constant = std::max(worst_constant, std::abs(constant[t] + 1.5));
    }
  }
  std::printf("line<->grid: conservative total error %.3e, consistent constant error %.3e\n",
              worst_total, worst_constant);
  EXPECT_LE(worst_total, 1e-12);
  EXPECT_LE(worst_constant, 1e-14);
}

TEST(OverlapMap, NodalGridControlVolumesAreHalvedAtTheBoundary) {
  // a cell grid mapped onto the nodal grid with the same cells: the end nodes
  // receive half a cell each
  const Mesh cells{"cells", UniformGrid{1, {0, 0, 0}, {0.5, 1, 1}, {4, 1, 1}, GridLocation::cell}};
  const Mesh nodes{"nodes", UniformGrid{1, {0, 0, 0}, {0.5, 1, 1}, {4, 1, 1}, GridLocation::node}};
  const auto mapped =
      build_operator(cells, nodes, Constraint::conservative).apply(std::vector<double>(4, 1.0));
  ASSERT_EQ(mapped.size(), 5u);
  EXPECT_DOUBLE_EQ(mapped[0], 0.5);
  EXPECT_DOUBLE_EQ(mapped[1], 1.0);
  EXPECT_DOUBLE_EQ(mapped[4], 0.5);
}

}  // namespace
}  // namespace cosim::mapping

#include <gtest/gtest.h>

#include <cstdio>

#include "cosim/error.hpp"
#include "mapping/build_operator.hpp"
#include "mapping_test_support.hpp"

namespace cosim::mapping {
namespace {

TEST(MappingOperator, AppliesElementMajorVectorFields) {
  const Mesh a{"a", UniformGrid{2, {0, 0, 0}, {0.1, 0.1, 1}, {10, 10, 1}, GridLocation::cell}};
  const Mesh b{"b",
               UniformGrid{2, {0.03, -0.02, 0}, {0.13, 0.11, 1}, {7, 9, 1}, GridLocation::node}};
  const Operator op = build_operator(a, b, Constraint::conservative);
  std::vector<double> momentum(a.size() * 3);
  for (std::size_t e = 0; e < a.size(); ++e)
    for (std::size_t c = 0; c < 3; ++c)
      momentum[e * 3 + c] = static_cast<double>(c + 1) * 0.5 + static_cast<double>(e % 7);
  const auto mapped = op.apply(momentum, 3);
  ASSERT_EQ(mapped.size(), b.size() * 3);
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<double> component(a.size());
    for (std::size_t e = 0; e < a.size(); ++e) component[e] = momentum[e * 3 + c];
    const auto alone = op.apply(component);
    double total_in = 0.0;
    double total_out = 0.0;
    for (std::size_t t = 0; t < b.size(); ++t) {
      EXPECT_NEAR(mapped[t * 3 + c], alone[t], 1e-14);
      total_out += mapped[t * 3 + c];
    }
    for (const double v : component) total_in += v;
    EXPECT_LE(testing::relative_difference(total_in, total_out), 1e-12);
  }
}

TEST(MappingOperator, RejectsWrongSizes) {
  const Mesh a{"a", UniformGrid{1, {0, 0, 0}, {1, 1, 1}, {4, 1, 1}, GridLocation::cell}};
  const Operator op = build_operator(a, a, Constraint::consistent);
  std::vector<double> target(4);
  EXPECT_THROW(op.apply(std::vector<double>(3), target), InputError);
  EXPECT_THROW(op.apply(std::vector<double>(8), target, 2), InputError);
  EXPECT_THROW(op.apply(std::vector<double>(4), target, 0), InputError);
  EXPECT_NO_THROW(op.apply(std::vector<double>(4), target));
}

TEST(MappingOperator, NamesRoundTrip) {
  for (const Constraint c : {Constraint::conservative, Constraint::consistent})
    EXPECT_EQ(constraint_from_string(to_string(c)), c);
  for (const Kernel k : {Kernel::linear, Kernel::quadratic_bspline})
    EXPECT_EQ(kernel_from_string(to_string(k)), k);
  EXPECT_THROW(constraint_from_string("conserving"), InputError);
  EXPECT_THROW(kernel_from_string("cubic"), InputError);
  EXPECT_EQ(constraint_for(Quantity::extensive), Constraint::conservative);
  EXPECT_EQ(constraint_for(Quantity::intensive), Constraint::consistent);
}

void expect_rejected_naming_both(const Mesh& from, const Mesh& to) {
  try {
    (void)build_operator(from, to, Constraint::conservative);
    FAIL() << "mapping " << from.name << " -> " << to.name << " accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    std::printf("rejected: %s\n", message.c_str());
    EXPECT_NE(message.find(from.name), std::string::npos);
    EXPECT_NE(message.find(to.name), std::string::npos);
    EXPECT_EQ(e.code(), ExitCode::bad_input);
  }
}

TEST(MappingOperator, UnsupportedPairsThrowNamingBothMeshes) {
  const Mesh grid2{"fluid_grid",
                   UniformGrid{2, {0, 0, 0}, {1, 1, 1}, {3, 3, 1}, GridLocation::cell}};
  const Mesh grid3{"mpm_grid", UniformGrid{3, {0, 0, 0}, {1, 1, 1}, {3, 3, 3}, GridLocation::node}};
  const Mesh line{"swe_line", NonUniformLine{{0.0, 0.5, 2.0}}};
  const Mesh points{"soil_particles", PointCloud{3, {0.5, 0.5, 0.5}, {0.1}}};
  const Mesh cells{"foam_cells", CellCloud{3, {0.5, 0.5, 0.5}, {0.1}}};
  expect_rejected_naming_both(grid2, grid3);
  expect_rejected_naming_both(line, grid2);
  expect_rejected_naming_both(points, cells);
  expect_rejected_naming_both(points, line);
  expect_rejected_naming_both(points, grid2);
  const Mesh broken{"broken_grid",
                    UniformGrid{3, {0, 0, 0}, {1, -1, 1}, {3, 3, 3}, GridLocation::cell}};
  EXPECT_THROW((void)build_operator(grid3, broken, Constraint::consistent), InputError);
  const Mesh empty_cloud{"no_particles", PointCloud{3, {}, {}}};
  EXPECT_THROW((void)build_operator(grid3, empty_cloud, Constraint::conservative), InputError);
  EXPECT_EQ(build_operator(empty_cloud, grid3, Constraint::consistent).empty_target_count(),
            grid3.size());
}

}  // namespace
}  // namespace cosim::mapping

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <variant>

#include "cosim/error.hpp"
#include "solver_1d_cases.hpp"

namespace {

swe::Solver1d make(std::vector<double> edges) {
  return {std::move(edges), {}, {}, swe_test::walls()};
}

TEST(Solver1dConstruction, RejectsTooFewOrNonIncreasingEdges) {
  EXPECT_THROW(make({}), cosim::InputError);
  EXPECT_THROW(make({1.0}), cosim::InputError);
  try {
    make({0.0, 0.1, 0.3, 0.3, 0.5});
    FAIL() << "equal edges accepted";
  } catch (const cosim::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("edges[3]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make({0.0, 0.2, 0.1}), cosim::InputError);
  EXPECT_THROW(make({0.0, std::numeric_limits<double>::quiet_NaN()}), cosim::InputError);
  EXPECT_NO_THROW(make({0.0, 0.5}));
}

TEST(Solver1dConstruction, RejectsBadPhysicsSchemeAndBoundaryValues) {
  swe::Physics p;
  p.gravity = 0.0;
  EXPECT_THROW(swe::Solver1d({0.0, 1.0}, p, {}, swe_test::walls()), cosim::InputError);
  swe::Scheme s;
  s.courant = 1.5;
  EXPECT_THROW(swe::Solver1d({0.0, 1.0}, {}, s, swe_test::walls()), cosim::InputError);
  const swe::Boundaries1d b{{swe::BoundaryKind::fixed_depth, -1.0}, {swe::BoundaryKind::wall, 0.0}};
  EXPECT_THROW(swe::Solver1d({0.0, 1.0}, {}, {}, b), cosim::InputError);
}

TEST(Solver1dState, RejectsNegativeDepthsAndWrongSizes) {
  swe::Solver1d s = make({0.0, 1.0, 2.0, 3.0});
  const std::vector<double> zero(3, 0.0);
  EXPECT_THROW(s.set_state(std::vector<double>{1.0, -1e-3, 1.0}, zero, {}), cosim::InputError);
  EXPECT_THROW(s.set_state(std::vector<double>{1.0, 1.0}, zero, {}), cosim::InputError);
  EXPECT_THROW(s.set_state(zero, std::vector<double>{1.0}, {}), cosim::InputError);
  EXPECT_THROW(s.set_bed(std::vector<double>{1.0}), cosim::InputError);
  EXPECT_THROW(s.step(-1.0), cosim::InputError);
  s.set_state(std::vector<double>{1.0, 0.0, 2.0}, std::vector<double>{0.5, 0.7, -1.0}, {});
  EXPECT_EQ(s.discharge_x()[0], 0.5);
  EXPECT_EQ(s.discharge_x()[1], 0.0) << "a dry cell carries no momentum";
}

TEST(Solver1dQueries, LocatesCellsAndReportsTheLine) {
  const std::vector<double> edges{0.0, 0.1, 0.35, 0.4, 1.0};
  swe::Solver1d s = make(edges);
  EXPECT_EQ(s.dimension(), 1);
  EXPECT_EQ(s.cell_count(), 4u);
  EXPECT_EQ(s.cell_at(0.0), 0u);
  EXPECT_EQ(s.cell_at(0.05), 0u);
  EXPECT_EQ(s.cell_at(0.1), 1u);
  EXPECT_EQ(s.cell_at(0.36), 2u);
  EXPECT_EQ(s.cell_at(1.0), 3u);
  EXPECT_EQ(s.cell_at(-0.01), 4u);
  EXPECT_EQ(s.cell_at(1.01), 4u);
  EXPECT_EQ(s.cell_at(std::numeric_limits<double>::quiet_NaN()), 4u);
  EXPECT_DOUBLE_EQ(s.cell_size(1), 0.25);
  const auto line = std::get<cosim::NonUniformLine>(s.cells());
  EXPECT_EQ(line.edges, edges);
  EXPECT_TRUE(s.discharge_y().empty());
}

TEST(Solver1dTimeStep, IsInfiniteWhenDryAndFollowsTheLocalWidthOtherwise) {
  swe::Solver1d s = make({0.0, 1.0, 1.5, 3.5});
  EXPECT_TRUE(std::isinf(s.stable_time_step()));
  // Still water 1 m deep: c = sqrt(g); the narrowest cell (0.5 m) limits.
  s.set_state(std::vector<double>{1.0, 1.0, 1.0}, std::vector<double>(3, 0.0), {});
  EXPECT_NEAR(s.stable_time_step(), 0.5 * 0.5 / std::sqrt(9.81), 1e-14);
  // One wet cell next to dry ones: its front runs at 2c.
  s.set_state(std::vector<double>{0.0, 0.0, 1.0}, std::vector<double>(3, 0.0), {});
  EXPECT_NEAR(s.stable_time_step(), 0.5 * 0.5 / (2.0 * std::sqrt(9.81)), 1e-14);
}

}  // namespace

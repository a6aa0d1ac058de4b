#include "ice/advection/advection_time_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {

TEST(AdvectionTimeStep, SumsTheLargestFaceSpeedOverDirections) {
  const ice::CellGrid<2> grid(Eigen::Vector2d(1.0, 2.0), Eigen::Vector2d(0.1, 0.2), {3, 2});
  ice::FaceField<2> u = ice::make_face_field(grid);
  std::fill(u[0].begin(), u[0].end(), 2.0);
  std::fill(u[1].begin(), u[1].end(), -1.0);
  EXPECT_DOUBLE_EQ(ice::advection_rate(grid, u), 2.0 / 0.1 + 1.0 / 0.2);
  // One fast face counts for both cells beside it.
  u[0][static_cast<std::size_t>(grid.face(0, {2, 1}))] = -5.0;
  EXPECT_DOUBLE_EQ(ice::advection_rate(grid, u), 5.0 / 0.1 + 1.0 / 0.2);
  EXPECT_DOUBLE_EQ(ice::advection_time_step(grid, u, 0.5), 0.5 / 55.0);
}

TEST(AdvectionTimeStep, IsUnboundedWhenNothingMoves) {
  const ice::CellGrid<3> grid(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2});
  EXPECT_TRUE(std::isinf(ice::advection_time_step(grid, ice::make_face_field(grid), 0.5)));
}

TEST(AdvectionTimeStep, RefusesFaceVelocitiesOfTheWrongSize) {
  const ice::CellGrid<1> grid(Eigen::Matrix<double, 1, 1>(0.0), Eigen::Matrix<double, 1, 1>(1.0),
                              {4});
  ice::FaceField<1> u{std::vector<double>(4, 1.0)};
  EXPECT_THROW(ice::advection_rate(grid, u), std::invalid_argument);
}

}  // namespace

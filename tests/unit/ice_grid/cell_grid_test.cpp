#include "ice/grid/cell_grid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "ice/grid/grid_fields.hpp"

namespace {

template <int Dim>
ice::CellGrid<Dim> make_grid(const std::array<int, Dim>& cells) {
  using Point = typename ice::CellGrid<Dim>::Point;
  Point origin;
  Point spacing;
  for (int d = 0; d < Dim; ++d) {
    origin[d] = -1.0 + 0.25 * d;
    spacing[d] = 0.1 * (d + 1);
  }
  return ice::CellGrid<Dim>(origin, spacing, cells);
}

// Every cell and face index maps to its (i, j, k) and back; faces and cells
// are each other's neighbours; counts, volume and areas follow the sizes.
template <int Dim>
void check_indexing(const std::array<int, Dim>& cells) {
  const ice::CellGrid<Dim> grid = make_grid<Dim>(cells);
  int count = 1;
  for (int d = 0; d < Dim; ++d) {
    count *= cells[d];
  }
  ASSERT_EQ(grid.cell_count(), count);
  EXPECT_DOUBLE_EQ(grid.cell_volume(), grid.spacing().prod());

  for (int c = 0; c < grid.cell_count(); ++c) {
    const auto ijk = grid.cell_ijk(c);
    ASSERT_EQ(grid.cell(ijk), c);
    const auto centre = grid.cell_centre(c);
    for (int d = 0; d < Dim; ++d) {
      EXPECT_DOUBLE_EQ(centre[d], grid.origin()[d] + (ijk[d] + 0.5) * grid.spacing()[d]);
      const int lower = grid.lower_face(d, c);
      const int upper = grid.upper_face(d, c);
      ASSERT_EQ(lower, grid.face(d, ijk));
      auto above = ijk;
      ++above[d];
      ASSERT_EQ(upper, grid.face(d, above));
      ASSERT_EQ(grid.upper_cell(d, lower), c);
      ASSERT_EQ(grid.lower_cell(d, upper), c);
      ASSERT_EQ(grid.lower_cell(d, lower), grid.neighbour(c, d, -1));
      ASSERT_EQ(grid.upper_cell(d, upper), grid.neighbour(c, d, +1));
      EXPECT_EQ(grid.neighbour(c, d, -1) == -1, ijk[d] == 0);
      EXPECT_EQ(grid.neighbour(c, d, +1) == -1, ijk[d] == cells[d] - 1);
      if (ijk[d] > 0) {
        auto below = ijk;
        --below[d];
        EXPECT_EQ(grid.neighbour(c, d, -1), grid.cell(below));
      }
      const auto face_centre = grid.face_centre(d, lower);
      EXPECT_NEAR(face_centre[d], centre[d] - 0.5 * grid.spacing()[d], 1e-15);
    }
  }

  for (int d = 0; d < Dim; ++d) {
    ASSERT_EQ(grid.face_count(d), count / cells[d] * (cells[d] + 1));
    EXPECT_DOUBLE_EQ(grid.face_area(d) * grid.spacing()[d], grid.cell_volume());
    int boundary_faces = 0;
    for (int f = 0; f < grid.face_count(d); ++f) {
      const auto ijk = grid.face_ijk(d, f);
      ASSERT_EQ(grid.face(d, ijk), f);
      const int lower = grid.lower_cell(d, f);
      const int upper = grid.upper_cell(d, f);
      ASSERT_FALSE(lower == -1 && upper == -1);
      boundary_faces += (lower == -1) + (upper == -1);
      EXPECT_EQ(lower == -1, ijk[d] == 0);
      EXPECT_EQ(upper == -1, ijk[d] == cells[d]);
    }
    EXPECT_EQ(boundary_faces, 2 * count / cells[d]);
  }
}

TEST(CellGrid, IndexRoundTrips1D) {
  check_indexing<1>({7});
}
TEST(CellGrid, IndexRoundTrips2D) {
  check_indexing<2>({5, 3});
}
TEST(CellGrid, IndexRoundTrips3D) {
  check_indexing<3>({4, 3, 5});
}
TEST(CellGrid, IndexRoundTripsWithOneCellAlongADirection) {
  check_indexing<3>({1, 4, 1});
}

TEST(CellGrid, CountsCellsAndFacesOfA3DBox) {
  const ice::CellGrid<3> grid = make_grid<3>({4, 3, 2});
  EXPECT_EQ(grid.cell_count(), 24);
  EXPECT_EQ(grid.face_count(0), 5 * 3 * 2);
  EXPECT_EQ(grid.face_count(1), 4 * 4 * 2);
  EXPECT_EQ(grid.face_count(2), 4 * 3 * 3);
  EXPECT_EQ(grid.stride(0), 1);
  EXPECT_EQ(grid.stride(1), 4);
  EXPECT_EQ(grid.stride(2), 12);
  EXPECT_EQ(grid.cell({1, 2, 1}), 1 + 4 * (2 + 3 * 1));
  EXPECT_NEAR((grid.upper() - grid.origin() - Eigen::Vector3d(0.4, 0.6, 0.6)).norm(), 0.0, 1e-15);
  const auto faces = ice::make_face_field(grid, 2.0);
  EXPECT_EQ(faces[1].size(), 32u);
  EXPECT_EQ(ice::make_cell_field(grid).size(), 24u);
}

TEST(CellGrid, RefusesBadSizes) {
  EXPECT_THROW(ice::CellGrid<2>(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.1, 0.0), {2, 2}),
               std::invalid_argument);
  EXPECT_THROW(ice::CellGrid<2>(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.1, 0.1), {2, 0}),
               std::invalid_argument);
  EXPECT_THROW(
      ice::CellGrid<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2000, 2000, 2000}),
      std::invalid_argument);
  EXPECT_THROW(ice::CellGrid<1>(Eigen::Matrix<double, 1, 1>(std::nan("")),
                                Eigen::Matrix<double, 1, 1>(1.0), {3}),
               std::invalid_argument);
}

}  // namespace

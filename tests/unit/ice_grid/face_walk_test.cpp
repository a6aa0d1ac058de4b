#include "ice/grid/face_walk.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

template <int Dim>
ice::CellGrid<Dim> make_grid(const std::array<int, Dim>& cells) {
  using Point = typename ice::CellGrid<Dim>::Point;
  return ice::CellGrid<Dim>(Point::Zero(), Point::Ones(), cells);
}

// for_each_face visits every face once with the cells lower_cell/upper_cell
// give; for_each_row covers every cell once and its face offsets give
// lower_face/upper_face.
template <int Dim>
void check_walks(const std::array<int, Dim>& cells) {
  const ice::CellGrid<Dim> grid = make_grid<Dim>(cells);
  for (int d = 0; d < Dim; ++d) {
    std::vector<int> visits(static_cast<std::size_t>(grid.face_count(d)), 0);
    ice::for_each_face(
        grid, d,
        [&](int f, int lower, int upper) {
          ++visits[static_cast<std::size_t>(f)];
          EXPECT_EQ(lower, grid.lower_cell(d, f));
          EXPECT_EQ(upper, grid.upper_cell(d, f));
          EXPECT_GE(lower, 0);
          EXPECT_GE(upper, 0);
        },
        [&](int f, int cell, bool upper_side) {
          ++visits[static_cast<std::size_t>(f)];
          EXPECT_EQ(upper_side ? grid.lower_cell(d, f) : grid.upper_cell(d, f), cell);
          EXPECT_EQ(upper_side ? grid.upper_cell(d, f) : grid.lower_cell(d, f), -1);
        });
    for (const int v : visits) EXPECT_EQ(v, 1);
    // The run form covers the same faces with the same cells.
    std::vector<int> run_visits(visits.size(), 0);
    const int s = grid.stride(d);
    ice::for_each_face_run(
        grid, d,
        [&](int first, int end, int upper_offset) {
          for (int f = first; f < end; ++f) {
            ++run_visits[static_cast<std::size_t>(f)];
            EXPECT_EQ(f - upper_offset, grid.upper_cell(d, f));
            EXPECT_EQ(f - upper_offset - s, grid.lower_cell(d, f));
          }
        },
        [&](int f, int cell, bool upper_side) {
          ++run_visits[static_cast<std::size_t>(f)];
          EXPECT_EQ(upper_side ? grid.lower_cell(d, f) : grid.upper_cell(d, f), cell);
        });
    for (const int v : run_visits) EXPECT_EQ(v, 1);
  }
  std::vector<int> visits(static_cast<std::size_t>(grid.cell_count()), 0);
  ice::for_each_row(grid, [&](int first, int length) {
    EXPECT_EQ(length, cells[0]);
    for (int c = first; c < first + length; ++c) {
      ++visits[static_cast<std::size_t>(c)];
      for (int d = 0; d < Dim; ++d) {
        EXPECT_EQ(c + ice::lower_face_offset(grid, d, first), grid.lower_face(d, c));
      }
    }
  });
  for (const int v : visits) EXPECT_EQ(v, 1);
}

TEST(FaceWalk, MatchesTheGridsIndexing1d) {
  check_walks<1>({1});
  check_walks<1>({7});
}

TEST(FaceWalk, MatchesTheGridsIndexing2d) {
  check_walks<2>({1, 1});
  check_walks<2>({5, 3});
  check_walks<2>({1, 4});
  check_walks<2>({4, 1});
}

TEST(FaceWalk, MatchesTheGridsIndexing3d) {
  check_walks<3>({3, 4, 5});
  check_walks<3>({1, 2, 1});
  check_walks<3>({2, 1, 3});
}

}  // namespace

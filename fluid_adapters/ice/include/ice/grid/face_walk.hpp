#pragma once

#include "ice/grid/cell_grid.hpp"

namespace ice {

// Visits every face normal to `normal` with the cells beside it, row by row
// along the normal, so that no index is divided (CellGrid::lower_cell and
// upper_cell divide per call):
//
//   interior(face, lower, upper)      for each face between two cells;
//   boundary(face, cell, upper_side)  for each face on the domain boundary,
//                                     `cell` the one inside, upper_side true
//                                     on the upper side.
//
// Faces normal to d of row `outer` are outer s (n + 1) + i s + inner
// (s = stride(d), n = cells[d], 0 <= i <= n, 0 <= inner < s), between cells
// i - 1 and i of the row: a face f away from the row's ends has the upper
// cell f - s outer and the lower cell one stride below, so the interior
// faces of a row form one contiguous range (a loop the compiler can
// vectorise when `interior` is simple).
//
// Always inlined: the callers' loop bodies then see their own local
// pointers, which is what lets the compiler vectorise them.
template <int Dim, class Interior, class Boundary>
[[gnu::always_inline]] inline void for_each_face(const CellGrid<Dim>& grid, int normal,
                                                 Interior&& interior, Boundary&& boundary) {
  const int s = grid.stride(normal);
  const int n = grid.cells()[normal];
  const int rows = grid.cell_count() / (s * n);
  for (int outer = 0; outer < rows; ++outer) {
    const int face_row = outer * s * (n + 1);
    const int to_upper_cell = s * outer;
    for (int f = face_row; f < face_row + s; ++f) boundary(f, f - to_upper_cell, false);
    for (int f = face_row + s; f < face_row + n * s; ++f) {
      interior(f, f - to_upper_cell - s, f - to_upper_cell);
    }
    for (int f = face_row + n * s; f < face_row + (n + 1) * s; ++f) {
      boundary(f, f - to_upper_cell - s, true);
    }
  }
}

// The same walk with the interior faces of a row handed over as one run:
// interior_run(first, end, upper_offset) for the faces first <= f < end,
// whose upper cell is f - upper_offset and lower cell f - upper_offset - s.
// For loops that the compiler vectorises only as their own loop (many
// arrays, see compute_face_velocities).
template <int Dim, class InteriorRun, class Boundary>
[[gnu::always_inline]] inline void for_each_face_run(const CellGrid<Dim>& grid, int normal,
                                                     InteriorRun&& interior_run,
                                                     Boundary&& boundary) {
  const int s = grid.stride(normal);
  const int n = grid.cells()[normal];
  const int rows = grid.cell_count() / (s * n);
  for (int outer = 0; outer < rows; ++outer) {
    const int face_row = outer * s * (n + 1);
    const int to_upper_cell = s * outer;
    for (int f = face_row; f < face_row + s; ++f) boundary(f, f - to_upper_cell, false);
    interior_run(face_row + s, face_row + n * s, to_upper_cell);
    for (int f = face_row + n * s; f < face_row + (n + 1) * s; ++f) {
      boundary(f, f - to_upper_cell - s, true);
    }
  }
}

// Visits the cells in rows along x: row(first, count) for each run of
// `count` consecutive cells starting at `first`. Within a row the lower face
// of a cell normal to any direction d is the cell's index plus
// lower_face_offset(grid, d, first), the upper face one stride(d) further.
template <int Dim, class Row>
void for_each_row(const CellGrid<Dim>& grid, Row&& row) {
  const int nx = grid.cells()[0];
  for (int first = 0; first < grid.cell_count(); first += nx) row(first, nx);
}

template <int Dim>
int lower_face_offset(const CellGrid<Dim>& grid, int normal, int row_first_cell) {
  return grid.lower_face(normal, row_first_cell) - row_first_cell;
}

}  // namespace ice

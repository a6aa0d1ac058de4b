#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ice/grid/cell_grid.hpp"

namespace ice {

// A cell-centred scalar: one value per cell, in the grid's flat cell order.
using CellField = std::vector<double>;

// Face-normal scalars: per direction d, one value per face normal to d, in
// the grid's flat face order (e.g. the face velocities U_FC). The cast keeps
// Dim out of deduction, so functions taking a CellGrid<Dim> and a
// FaceField<Dim> deduce it from the grid.
template <int Dim>
using FaceField = std::array<std::vector<double>, static_cast<std::size_t>(Dim)>;

template <int Dim>
CellField make_cell_field(const CellGrid<Dim>& grid, double value = 0.0) {
  return CellField(static_cast<std::size_t>(grid.cell_count()), value);
}

template <int Dim>
FaceField<Dim> make_face_field(const CellGrid<Dim>& grid, double value = 0.0) {
  FaceField<Dim> field;
  for (int d = 0; d < Dim; ++d) {
    field[d].assign(static_cast<std::size_t>(grid.face_count(d)), value);
  }
  return field;
}

}  // namespace ice

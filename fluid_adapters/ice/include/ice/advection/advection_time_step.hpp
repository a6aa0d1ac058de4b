#pragma once

#include <span>

#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"

namespace ice {

// The advective rate of the grid, max over cells of sum_d |U_d| / dx_d with
// |U_d| the larger speed on the cell's two faces normal to d [1/s]. The
// advection step is stable (every face's |U| dt / dx <= 1, and a donor cell
// loses at most its content) for dt <= courant / rate with courant <= 1; the
// limited schemes keep extrema bounded in 2D and 3D for courant <= 1/2.
// `counted` (one flag per cell, or empty for every cell) limits the max to
// the flagged cells: a block's own cells in a decomposed grid.
template <int Dim>
double advection_rate(const CellGrid<Dim>& grid, const FaceField<Dim>& face_velocity,
                      std::span<const unsigned char> counted = {});

// courant / advection_rate, or +infinity when nothing moves. Throws
// std::invalid_argument for face velocities of the wrong size.
template <int Dim>
double advection_time_step(const CellGrid<Dim>& grid, const FaceField<Dim>& face_velocity,
                           double courant);

}  // namespace ice

#pragma once

#include <cstddef>

#include "swe/physics.hpp"
#include "swe/solver_1d.hpp"

namespace swe::solver_1d {

// Fills the two ghost cells on each side of depth and discharge arrays of
// n + 4 values (cell i at i + 2) from the boundary conditions (the rules are
// listed in swe/solver_1d.hpp).
void fill_ghost_cells(const Boundaries1d& boundaries, const Physics& physics, std::size_t n,
                      double* h, double* q);

// Copies the adjacent interior bed into the ghost cells.
void fill_ghost_bed(std::size_t n, double* bed);

// Throws cosim::InputError for a negative or non-finite boundary value.
void check_boundaries(const Boundaries1d& boundaries);

}  // namespace swe::solver_1d

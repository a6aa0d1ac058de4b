#pragma once

#include <array>
#include <vector>

#include "solver_2d/padded_fields.hpp"
#include "swe/physics.hpp"
#include "swe/solver_2d.hpp"

namespace swe::solver_2d {

// Fills the two ghost layers of every side of `fields` (conserved variables,
// bed and primitives) from the boundary conditions. Each side is handled by
// the same code with its normal and tangential components:
//   wall             ghost layer k mirrors interior cell k-1 (bed included), normal velocity
//   negated; transmissive     both layers copy the adjacent interior cell; inflow_discharge depth
//   and bed of the adjacent cell (the critical depth
//                    (q^2/g)^(1/3) if it is dry), normal discharge q into the domain,
//                    no tangential velocity;
//   fixed_depth      the given depth, normal velocity from the outgoing Riemann
//                    invariant u_n +- 2 sqrt(g h) of the adjacent cell,
//                    tangential velocity copied.
// Sides marked in `linked` (x_min, x_max, y_min, y_max) face another block
// of a decomposed grid and are left alone.
void fill_ghost_cells(const PaddedLayout& layout, const Boundaries2d& boundaries,
                      const std::array<bool, 4>& linked, const Physics& physics,
                      PaddedFields& fields, std::vector<double>& bed);

// The primitives of the ghost cells of the linked sides, from their
// conserved variables and bed (filled by the neighbouring blocks).
void update_linked_ghost_primitives(const PaddedLayout& layout, const std::array<bool, 4>& linked,
                                    const Physics& physics, PaddedFields& fields,
                                    const std::vector<double>& bed);

}  // namespace swe::solver_2d

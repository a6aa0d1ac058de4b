#pragma once

#include <span>
#include <vector>

#include "mpm/coupling/body_roles.hpp"
#include "mpm/coupling/exchange_grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// The pore pressure p given per exchange cell acts on the solid through
// -phi_s grad p (Tran et al., MPMICE, eq. 7); the solver's internal force
// holds only the effective stress. Per particle, with p and grad p from the
// consistent (multilinear, constant- and linear-exact) interpolation:
//   particles.pore_pressure[p] = p(x_p)                (porous bodies)
//   force[p] = -(1 - n_p) V_p grad p(x_p)               (deformable bodies; 0 for rigid)
// Non-porous deformable bodies have n_p = 0: their force -V_p grad p is the
// resultant of the fluid pressure on an immersed impermeable body.
// Returns the total force [N] (per unit depth in 2D).
template <int Dim>
Vec<Dim> pore_pressure_force(const ExchangeGrid<Dim>& grid, std::span<const double> pressure,
                             Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                             std::vector<Vec<Dim>>& force);

}  // namespace mpm::coupling

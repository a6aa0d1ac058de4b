#pragma once

#include <vector>

#include "swe/case/case_description.hpp"
#include "swe/solver.hpp"

namespace swe {

// The traction the water exerts on the bed per cell [Pa = force per unit
// horizontal area], dimension + 1 components: horizontal (x[, y]) then
// vertical (Zheng et al., eq. 10; Algorithm 1, line 20), for the soil solver
// to apply on its surface particles.
//
// Shear: Manning's bed stress rho g M_b^2 u |u| / h^(1/3) along the flow on
// wet cells (the reaction of the friction of eq. 36).
// Pressure, BedPressure::hydrostatic: vertical -rho g h; horizontal, per
// face, the bed's share of the hydrostatic reconstruction,
//   F = rho g/2 [(h_l^2 - h*_l^2) - (h_r^2 - h*_r^2)]   per unit face length,
// split half to each side's cell: the reaction of the bed force the solver
// puts on the water (first order), so a step in the bed feels the full
// hydrostatic thrust of the water against it and a lake at rest pushes a
// flat bed only downwards.
// Pressure, BedPressure::excess: vertical -rho g max(0, eta - eta_0) on wet
// cells, eta_0 the free surface above the cell at the start
// (spec.initial_surface); no horizontal pressure.
std::vector<double> bed_traction(const Solver& solver, const CouplingSpec& spec);

}  // namespace swe

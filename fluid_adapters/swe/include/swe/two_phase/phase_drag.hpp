#pragma once

#include <cstddef>
#include <span>

#include "cosim/exchange/generalised_drag.hpp"
#include "swe/two_phase/solid_layer.hpp"

namespace swe {

// The generalised drag's parameters with j = 2 (quadratic, the paper's settings).
inline cosim::exchange::GeneralisedDragParameters quadratic_drag() {
  cosim::exchange::GeneralisedDragParameters drag;
  drag.exponent = 2.0;
  return drag;
}

// The two-phase closure of the shallow water over a solid layer.
struct TwoPhaseParameters {
  // Pudasaini's generalised drag as van den Bout et al., OpenLISEM Hazard,
  // eqs. 61-64 split it (cosim/exchange/generalised_drag.hpp). j = 1 is
  // linear, j = 2 quadratic (the formula's reading, not the text's). Its
  // gravity is replaced by the solver's.
  cosim::exchange::GeneralisedDragParameters drag = quadratic_drag();
  double solid_density = 2650.0;  // rho_s of the grains [kg/m^3]
  double fluid_viscosity = 1e-3;  // eta_f [Pa s]
  // The virtual mass V = alpha_c rho_f C_vm (eq. 65) in the relaxation.
  bool virtual_mass = true;
};

// The mixture of one cell: solid depth h_s under fluid depth h_f, phase c of
// bulk density rho_c made of grains of density rho_s (solid fraction
// phi = (rho_c - rho_f) / (rho_s - rho_f) within phase c) and the fluid they
// confine. alpha_c = h_s / H, alpha_s = phi alpha_c,
// f_fc = (1 - phi) alpha_c / (1 - alpha_s), so that the mixture's
// confined_density() is rho_c. Throws cosim::InputError when rho_c is not in
// (rho_f, rho_s] or a depth is not positive.
cosim::exchange::DebrisMixture cell_mixture(double solid_depth, double fluid_depth, double density,
                                            double structured_share,
                                            const TwoPhaseParameters& parameters,
                                            double fluid_density);

// The drag between the layer's solids and the free fluid over dt (operator
// splitting, after the fluid's step), on every cell where both phases are
// present (h_s > dry_depth and h_f > dry_depth; other cells are left alone):
// the coefficient C of the cell's mixture (generalised_drag_coefficient, per
// unit mixture volume), then cosim::exchange::relax_drag with the weights
// alpha_c rho_c and alpha_u rho_f, V = alpha_c rho_f C_vm (or 0), frozen over
// dt. The fluid's discharges h (new u_u) and the layer's velocity (new u_c)
// are written back; the impulse the solids receive, J H |cell| [kg m/s]
// (+x, +y; the fluid receives its opposite), is added to impulse_x/_y.
// Per cell rho_c h_s u_c + rho_f h_f u_u is kept to round-off.
// hv and impulse_y are empty in 1D. Cells numbered as the layer's.
void exchange_momentum(const TwoPhaseParameters& parameters, double fluid_density, double dry_depth,
                       double cell_area, double dt, std::span<const double> h, std::span<double> hu,
                       std::span<double> hv, SolidLayer& layer, std::span<double> impulse_x,
                       std::span<double> impulse_y);

}  // namespace swe

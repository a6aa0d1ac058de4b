#pragma once

#include <span>

// The drag between two phases in one cell over a step, integrated exactly in
// time with the coefficients frozen at the step's start. Phase c (solids)
// receives f = C (u_u - u_c)|u_u - u_c|^(j-1) per unit volume and phase u
// (fluid) -f; the virtual mass force V d(u_u - u_c)/dt acts the same way
// (van den Bout et al., OpenLISEM Hazard 2.0a, eqs. 50-53, 61, 65). With
// weights w = alpha rho and mu = 1/w_c + 1/w_u, the relative velocity
// w = u_u - u_c keeps its direction and its magnitude obeys
//
//   d|w|/dt = -a |w|^j,  a = C mu / (1 + V mu),
//
// so that |w(dt)| = |w0| exp(-a dt) for j = 1 and
// |w(dt)| = |w0| (1 + (j - 1) a |w0|^(j-1) dt)^(-1/(j-1)) otherwise.
// Backward Euler (as in ICE's exchange) would damp a linear drag by
// 1 / (1 + a dt) instead of exp(-a dt); the exact factor is just as stable
// at any a dt and leaves no time-step error for a frozen coefficient.
//
// Momentum: c receives the impulse J = (w0 - w(dt)) / mu per unit volume and
// u receives -J, so w_c u_c + w_u u_u is kept to round-off.
namespace cosim::exchange {

struct DragRelaxation {
  double solid_weight = 0;      // w_c = alpha_c rho_c [kg m^-3]; 0 = absent
  double fluid_weight = 0;      // w_u = alpha_u rho_u [kg m^-3]; 0 = absent
  double drag_coefficient = 0;  // C [kg m^(-2-j) s^(j-2)], may be +inf (phases locked)
  double exponent = 1;          // j >= 1
  double virtual_mass = 0;      // V = alpha_c rho_u C_vm [kg m^-3]
};

// Relaxes `solid_velocity` and `fluid_velocity` (same 1 to 3 components) in
// place over `dt` and writes the impulse density J given to the solid
// [kg m^-2 s^-1] into `solid_impulse` (same size; may be empty). Nothing
// changes when a weight is 0, C = 0 or dt = 0. Throws std::invalid_argument
// on mismatched sizes, a negative or non-finite weight, dt or V, C < 0 or
// NaN, j < 1, or a non-finite velocity.
void relax_drag(const DragRelaxation& cell, double dt, std::span<double> solid_velocity,
                std::span<double> fluid_velocity, std::span<double> solid_impulse = {});

// The fraction of the relative speed the drag takes away over dt,
// 1 - |w(dt)| / |w0| in [0, 1], accurate also where it is tiny.
double relaxed_fraction(double rate, double exponent, double relative_speed, double dt);

}  // namespace cosim::exchange

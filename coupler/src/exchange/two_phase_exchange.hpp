#pragma once

#include <span>

#include "exchange/drag_law.hpp"

// The coupler's per-window momentum exchange between a fluid and a porous
// solid on the cells of the exchange mesh (architecture.md §4). Arrays run over
// cells; vector quantities are element-major with `dim` components per cell
// (u[cell * dim + k]).
namespace cosim::exchange {

struct PhaseFields {
  std::span<const double> bulk_density;  // rho_bar [kg m^-3], one per cell; 0 = absent
  std::span<const double> velocity;      // U* entering the exchange [m s^-1], dim per cell
};

struct PorousMedium {
  std::span<const double> solid_fraction;  // phi_s [-], one per cell
  std::span<const double> grain_size;      // [m]; needed only if the law reads it per cell
  std::span<const double> permeability;    // [m^2]; idem
};

struct TwoPhaseExchangeResult {
  std::span<double> fluid_velocity_increment;  // Delta U_f [m s^-1], dim per cell
  std::span<double> solid_velocity_increment;  // Delta U_s [m s^-1], dim per cell
  // Momentum each phase receives in the cell, rho_bar Delta U V [kg m s^-1]
  // (extensive, for conservative mapping); solid_impulse = -fluid_impulse.
  std::span<double> fluid_impulse;
  std::span<double> solid_impulse;
  std::span<double> drag_coefficient;  // optional: K per cell [kg m^-3 s^-1]; may be empty
};

// For each cell: K from `law` (fluid true density rho_bar_f / (1 - phi_s),
// lagged relative speed |U*_s - U*_f|), then the closed-form implicit exchange
// with beta_f = dt K / rho_bar_f and beta_s = dt K / rho_bar_s (Tran et al.,
// MPMICE, eq. 131). Cells where either phase is absent get zero increments.
// Throws std::invalid_argument on array sizes that do not match, and
// cosim::NumericalError naming the cell on a non-finite velocity, a negative
// or non-finite density, phi_s outside [0, 1], a missing or non-positive
// per-cell grain size/permeability the law reads, or a negative K.
void exchange_two_phase(const DragLaw& law, int dim, double dt, std::span<const double> cell_volume,
                        const PhaseFields& fluid, const PhaseFields& solid,
                        const PorousMedium& medium, const TwoPhaseExchangeResult& result);

}  // namespace cosim::exchange

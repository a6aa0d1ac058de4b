#pragma once

#include <cstddef>
#include <limits>
#include <span>

#include "cosim/mesh.hpp"

namespace cosim::cplscheme {

// The longest window an explicit (staggered) exchange of porosity and pore
// pressure survives (architecture.md §3): undrained, the pore fluid carries the
// load, so the mixture's bulk modulus is about K_f / n (the skeleton's
// stiffness is far smaller) and its inertia that of both phases,
//   c = sqrt(K_f / (n (rho_bar_f + rho_bar_s))),
// and the window must let that wave cross no more than one exchange cell,
//   window <= h / c,
// h the cell's smallest width. Cells without solid, or without pores, carry
// no such wave; a held solid (immense bulk density) does not answer the
// pressure at all.
struct ExplicitStabilityBound {
  double window = std::numeric_limits<double>::infinity();  // [s]
  double wave_speed = 0.0;                                  // in the limiting cell [m/s]
  double cell_width = 0.0;                                  // of the limiting cell [m]
  double porosity = 0.0;                                    // of the limiting cell
  std::size_t cell = 0;
  bool applies() const { return window < std::numeric_limits<double>::infinity(); }
};

// All fields per cell of `mesh`: solid fraction, the phases' bulk densities
// [kg/m^3] and the pore fluid's bulk modulus [Pa].
ExplicitStabilityBound undrained_wave_bound(const Mesh& mesh,
                                            std::span<const double> solid_fraction,
                                            std::span<const double> solid_bulk_density,
                                            std::span<const double> fluid_bulk_density,
                                            std::span<const double> fluid_bulk_modulus);

}  // namespace cosim::cplscheme

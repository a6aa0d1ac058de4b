#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ice/grid/grid_fields.hpp"

namespace ice {

// The cell-centred state of one fluid material. bulk_density, velocity and
// temperature are the primary variables; density, volume_fraction and
// specific_volume follow from the pressure equilibration (Tran et al.,
// MPMICE, eqs. 42-43): phi = rhobar / rho, v = 1 / rho.
template <int Dim>
struct MaterialState {
  CellField bulk_density;                                         // rhobar [kg/m3]
  std::array<CellField, static_cast<std::size_t>(Dim)> velocity;  // U [m/s]
  CellField temperature;                                          // T [K]
  CellField density;                                              // rho, intrinsic [kg/m3]
  CellField volume_fraction;                                      // phi [-]
  CellField specific_volume;  // v [m3/kg], as advected (eqs. 75-84)
};

// The state of all fluid materials and what they share per cell: the
// equilibrium pressure and, from a coupled porous solid, the porosity n
// (the fluids' volume fractions sum to it) and the solid velocity that
// enters the divergence constraint (eq. 75's mixture velocity).
template <int Dim>
struct FluidState {
  CellField pressure;                                                   // P [Pa]
  CellField porosity;                                                   // n [-], 1 without a solid
  std::array<CellField, static_cast<std::size_t>(Dim)> solid_velocity;  // U_s [m/s]
  std::vector<MaterialState<Dim>> materials;
};

}  // namespace ice

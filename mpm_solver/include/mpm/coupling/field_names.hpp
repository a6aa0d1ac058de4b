#pragma once

#include <string_view>

#include "cosim/fields.hpp"

// The meshes the MPM declares and the fields it exchanges on them (their
// units and meanings: cosim/fields.hpp).
namespace mpm::coupling::names {

// Cell-centred Dim-D grid over the MPM grid (exchange grid).
inline constexpr const char* exchange_mesh = "mpm_grid";
// Cell-centred (Dim-1)-D grid over the MPM grid's horizontal extent.
inline constexpr const char* surface_mesh = "mpm_surface";

// On mpm_grid, written [1, m/s, kg/m^3, m^2, m].
inline constexpr const char* solid_fraction = cosim::fields::solid_fraction.name;
inline constexpr const char* solid_velocity = cosim::fields::solid_velocity.name;
inline constexpr const char* solid_bulk_density = cosim::fields::solid_bulk_density.name;
inline constexpr const char* permeability = cosim::fields::permeability.name;
inline constexpr const char* grain_size = cosim::fields::grain_size.name;
// On mpm_grid, written [m/s] (Dim components): the solids' volume flux
// sum_i phi_i U_i per cell, the solid term of the mixture's continuity
// (Tran et al., MPMICE, eq. 75). It differs from phi_s solid_velocity where
// a held body (a rigid bed at rest) shares a cell with a moving one: there
// solid_velocity is the moving body's (the drag's relative velocity) while
// phi_s counts both.
inline constexpr const char* solid_volume_flux = cosim::fields::solid_volume_flux.name;
// On mpm_grid, read: pore pressure [Pa] (intensive state) and the momentum
// the solid receives from the implicit exchange [kg m/s] (extensive window
// integral, Dim components).
inline constexpr const char* pore_pressure = cosim::fields::pore_pressure.name;
// On mpm_grid, read instead of taking -phi_s grad p from pore_pressure: the
// force the pore pressure exerts on the solid in each cell [N], as the fluid
// solver discretises it (extensive state, Dim components), so that the solid
// and the fluid share one pressure gradient.
inline constexpr const char* pore_pressure_force = cosim::fields::pore_pressure_force.name;
inline constexpr const char* impulse = cosim::fields::momentum_exchange_impulse.name;
// On mpm_grid, for thermal cases: written [K, J/(m^3 K)] (intensive state),
// and the heat the solid receives from the implicit energy exchange [J]
// read (extensive window integral, 1 component).
inline constexpr const char* solid_temperature = cosim::fields::solid_temperature.name;
inline constexpr const char* solid_heat_capacity = cosim::fields::solid_heat_capacity.name;
inline constexpr const char* heat = cosim::fields::heat_exchange_energy.name;
// The exchange grid's fields that need a case that conducts heat.
inline bool is_thermal(std::string_view field) {
  return field == solid_temperature || field == solid_heat_capacity || field == heat;
}
// On mpm_surface: bed elevation [m] written; bed traction [Pa], Dim
// components (horizontal shear, then the vertical normal component), read.
inline constexpr const char* bed_elevation = cosim::fields::bed_elevation.name;
inline constexpr const char* bed_traction = cosim::fields::bed_traction.name;

}  // namespace mpm::coupling::names

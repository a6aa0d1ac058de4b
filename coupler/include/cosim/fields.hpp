#pragma once

#include <span>
#include <string>
#include <string_view>

#include "cosim/field.hpp"

// Every field the solvers exchange, in one place: its name on the wire, its
// SI unit, how it is mapped (intensive: consistently; extensive:
// conservatively), how it relates to the window (its value at the window's
// end, or its integral over the window) and what it means. Solvers declare
// their fields from these entries and the coupler's exchanges find them by
// these names; `cosim help-fields` lists them.
namespace cosim::fields {

// How many components a field has in a d-dimensional coupled problem.
enum class Components : std::uint8_t {
  one,        // a scalar
  dimension,  // a vector of d components (x, y[, z])
};

struct Field {
  const char* name;
  const char* unit;
  Quantity quantity;
  TimeTreatment time;
  Components components;
  const char* meaning;

  // The participant's declaration of this field on `mesh`; bounds and
  // `optional` are the declaring side's to set.
  FieldSpec on(std::string mesh, int dimension) const;
  int components_in(int dimension) const { return components == Components::one ? 1 : dimension; }
};

// The implicit momentum exchange between a porous solid and its pore fluid
// (Tran et al., MPMICE, eqs. 131-133), on the exchange grid.
inline constexpr Field solid_fraction{
    .name = "solid_fraction",
    .unit = "1",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "phi_s: the solid's volume fraction of a cell (soil writes)"};
inline constexpr Field solid_velocity{.name = "solid_velocity",
                                      .unit = "m/s",
                                      .quantity = Quantity::intensive,
                                      .time = TimeTreatment::state,
                                      .components = Components::dimension,
                                      .meaning = "U_s: the solid's velocity (soil writes)"};
inline constexpr Field solid_bulk_density{
    .name = "solid_bulk_density",
    .unit = "kg/m^3",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "rho_bar_s = phi_s rho_s: the solid's mass per cell volume (soil writes)"};
inline constexpr Field permeability{
    .name = "permeability",
    .unit = "m^2",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "k: intrinsic permeability, for drag laws that read it per cell (soil writes)"};
inline constexpr Field grain_size{
    .name = "grain_size",
    .unit = "m",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "d: grain diameter, for drag laws that read it per cell (soil writes)"};
inline constexpr Field solid_volume_flux{
    .name = "solid_volume_flux",
    .unit = "m/s",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::dimension,
    .meaning =
        "sum_i phi_i U_i: the solids' volume flux, the solid term of the mixture's continuity "
        "(Tran et al., MPMICE, eq. 75; soil writes, an optional read)"};
inline constexpr Field fluid_velocity{.name = "fluid_velocity",
                                      .unit = "m/s",
                                      .quantity = Quantity::intensive,
                                      .time = TimeTreatment::state,
                                      .components = Components::dimension,
                                      .meaning = "U_f: the pore fluid's velocity (fluid writes)"};
inline constexpr Field fluid_bulk_density{
    .name = "fluid_bulk_density",
    .unit = "kg/m^3",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "rho_bar_f = n rho_f: the pore fluid's mass per cell volume (fluid writes)"};
inline constexpr Field pore_fluid_bulk_modulus{
    .name = "pore_fluid_bulk_modulus",
    .unit = "Pa",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning =
        "K_f: the bulk modulus of the fluids in the pores, from which the coupler bounds an "
        "explicit window (compressible fluids write)"};
inline constexpr Field pore_pressure{
    .name = "pore_pressure",
    .unit = "Pa",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "p: the pore fluid's pressure (fluid writes, soil reads)"};
inline constexpr Field pore_pressure_force{
    .name = "pore_pressure_force",
    .unit = "N",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::state,
    .components = Components::dimension,
    .meaning =
        "-phi_s V grad p: the force of the pore pressure on the solid in a cell, as the fluid "
        "discretises it (fluid writes, soil reads instead of pore_pressure's gradient)"};
inline constexpr Field momentum_exchange_impulse{
    .name = "momentum_exchange_impulse",
    .unit = "kg m/s",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::integral,
    .components = Components::dimension,
    .meaning =
        "the momentum a phase receives from the drag over the window (the coupler, or a fluid "
        "solving the exchange itself, writes; both read)"};
inline constexpr Field drag_coefficient{
    .name = "drag_coefficient",
    .unit = "kg/(m^3 s)",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning =
        "K: the drag law's coefficient, for a fluid that solves the exchange in its own steps (the "
        "coupler writes)"};
inline constexpr Field water_fraction{
    .name = "water_fraction",
    .unit = "1",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "alpha_w: the water's volume fraction of the fluid (two-phase fluids write)"};

// The implicit energy exchange between a solid and its fluid (Tran et al.,
// MPMICE, eq. 23), on the exchange grid.
inline constexpr Field solid_temperature{.name = "solid_temperature",
                                         .unit = "K",
                                         .quantity = Quantity::intensive,
                                         .time = TimeTreatment::state,
                                         .components = Components::one,
                                         .meaning = "T_s: the solid's temperature (soil writes)"};
inline constexpr Field solid_heat_capacity{
    .name = "solid_heat_capacity",
    .unit = "J/(m^3 K)",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "rho_bar_s c_s: the solid's heat capacity per cell volume (soil writes)"};
inline constexpr Field fluid_temperature{.name = "fluid_temperature",
                                         .unit = "K",
                                         .quantity = Quantity::intensive,
                                         .time = TimeTreatment::state,
                                         .components = Components::one,
                                         .meaning = "T_f: the fluid's temperature (fluid writes)"};
inline constexpr Field fluid_heat_capacity{
    .name = "fluid_heat_capacity",
    .unit = "J/(m^3 K)",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "sum rho_bar_f c_v: the fluids' heat capacity per cell volume (fluid writes)"};
inline constexpr Field heat_exchange_energy{
    .name = "heat_exchange_energy",
    .unit = "J",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::integral,
    .components = Components::one,
    .meaning =
        "the heat a phase receives from the energy exchange over the window (the coupler writes)"};

// A deforming bed under shallow water, on the bed's surface grid.
inline constexpr Field bed_elevation{
    .name = "bed_elevation",
    .unit = "m",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "z_b: the bed's elevation (soil writes, water reads)"};
inline constexpr Field bed_traction{
    .name = "bed_traction",
    .unit = "Pa",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::dimension,
    .meaning =
        "the water's traction on the bed: the horizontal shear, then the vertical normal "
        "component; d components on a (d-1)-dimensional surface (water writes, soil reads)"};

// A depth-averaged mass (material points in plan view) under a two-phase
// shallow water (van den Bout et al., OpenLISEM Hazard, eqs. 47-65): the
// points' columns summed onto the water's cells, the water's drag and
// surface back to the points.
inline constexpr Field column_volume{
    .name = "column_volume",
    .unit = "m^3",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "V: the columns' volume of solids and the fluid they confine (mass writes)"};
inline constexpr Field column_mass{.name = "column_mass",
                                   .unit = "kg",
                                   .quantity = Quantity::extensive,
                                   .time = TimeTreatment::state,
                                   .components = Components::one,
                                   .meaning = "m: the columns' mass (mass writes)"};
inline constexpr Field column_momentum{.name = "column_momentum",
                                       .unit = "kg m/s",
                                       .quantity = Quantity::extensive,
                                       .time = TimeTreatment::state,
                                       .components = Components::dimension,
                                       .meaning = "m u: the columns' momentum (mass writes)"};
inline constexpr Field structured_mass{
    .name = "structured_mass",
    .unit = "kg",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning = "f_sc m: the part of the columns' mass still bound in blocks (mass writes)"};
inline constexpr Field released_fluid_volume{
    .name = "released_fluid_volume",
    .unit = "m^3",
    .quantity = Quantity::extensive,
    .time = TimeTreatment::integral,
    .components = Components::one,
    .meaning =
        "the confined fluid the fragmenting columns released over the window (eq. 27; "
        "mass writes, water reads as a source)"};
inline constexpr Field free_surface_elevation{
    .name = "free_surface_elevation",
    .unit = "m",
    .quantity = Quantity::intensive,
    .time = TimeTreatment::state,
    .components = Components::one,
    .meaning =
        "eta: the water's surface; over dry cells the level of the nearest water (water "
        "writes, mass reads for its buoyancy)"};

// Every entry above, in that order.
std::span<const Field* const> all();
// The entry named `name`, or nullptr.
const Field* find(std::string_view name);
// The catalogue as text (`cosim help-fields`).
std::string help();

}  // namespace cosim::fields

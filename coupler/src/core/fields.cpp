#include "cosim/fields.hpp"

#include <fmt/format.h>

#include <array>

namespace cosim::fields {

FieldSpec Field::on(std::string mesh, int dimension) const {
  FieldSpec spec;
  spec.name = name;
  spec.mesh = std::move(mesh);
  spec.components = components_in(dimension);
  spec.unit = unit;
  spec.quantity = quantity;
  spec.time = time;
  return spec;
}

namespace {

constexpr std::array catalogue{&solid_fraction,
                               &solid_velocity,
                               &solid_bulk_density,
                               &permeability,
                               &grain_size,
                               &solid_volume_flux,
                               &fluid_velocity,
                               &fluid_bulk_density,
                               &pore_fluid_bulk_modulus,
                               &pore_pressure,
                               &pore_pressure_force,
                               &momentum_exchange_impulse,
                               &drag_coefficient,
                               &water_fraction,
                               &solid_temperature,
                               &solid_heat_capacity,
                               &fluid_temperature,
                               &fluid_heat_capacity,
                               &heat_exchange_energy,
                               &bed_elevation,
                               &bed_traction,
                               &column_volume,
                               &column_mass,
                               &column_momentum,
                               &structured_mass,
                               &released_fluid_volume,
                               &free_surface_elevation};

}  // namespace

std::span<const Field* const> all() {
  return catalogue;
}

const Field* find(std::string_view name) {
  for (const Field* field : catalogue)
    if (name == field->name) return field;
  return nullptr;
}

std::string help() {
  std::string text =
      "Fields the solvers exchange (name, unit, mapping, window, components, meaning).\n"
      "intensive: mapped consistently (weighted averages); extensive: conservatively (totals "
      "kept).\nstate: the value at the window's end; integral: the window's time integral.\n"
      "d: the coupled problem's dimension.\n\n";
  for (const Field* field : catalogue)
    text += fmt::format("{:<26} {:<11} {:<10} {:<9} {:<2} {}\n", field->name, field->unit,
                        to_string(field->quantity), to_string(field->time),
                        field->components == Components::one ? "1" : "d", field->meaning);
  return text;
}

}  // namespace cosim::fields

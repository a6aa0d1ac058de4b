#include "exchange/kozeny_carman.hpp"

#include <limits>

#include "exchange/drag_law_keys.hpp"

namespace cosim::exchange {

using drag_law_keys::checked_cell_value;

KozenyCarman::KozenyCarman(double fluid_viscosity, Basis basis, std::optional<double> value)
    : fluid_viscosity_(fluid_viscosity), basis_(basis), value_(value) {}

CellInput KozenyCarman::cell_input() const {
  if (value_) return CellInput::none;
  return basis_ == Basis::grain_size ? CellInput::grain_size : CellInput::permeability;
}

double KozenyCarman::coefficient(const DragInput& input) const {
  const double phi_s = input.solid_fraction;
  const double n = 1.0 - phi_s;
  const double mu = fluid_viscosity_;
  if (basis_ == Basis::permeability) {
    const double kappa = value_ ? *value_ : checked_cell_value(input.permeability, "permeability");
    return n * n * mu / kappa;  // Tran et al., eq. 30
  }
  if (n <= 0) return std::numeric_limits<double>::infinity();
  const double d = value_ ? *value_ : checked_cell_value(input.grain_size, "grain size");
  return 180.0 * phi_s * phi_s * mu / (d * d * n);  // Tran et al., eq. 29
}

config::Schema KozenyCarman::schema() {
  config::Schema schema = drag_law_keys::base_schema(
      law,
      "Kozeny-Carman drag, linear in the relative velocity (Darcy flow; Tran et al., MPMICE, "
      "eqs. 29-30).");
  drag_law_keys::add_fluid_viscosity(schema);
  drag_law_keys::add_bed_length_scale(schema);
  return schema;
}

std::unique_ptr<DragLaw> KozenyCarman::make(const config::Node& node) {
  const drag_law_keys::BedLengthScale scale = drag_law_keys::read_bed_length_scale(node);
  return std::make_unique<KozenyCarman>(
      node["fluid_viscosity"].as<double>(),
      scale.from_grain_size ? Basis::grain_size : Basis::permeability, scale.value);
}

}  // namespace cosim::exchange

#include "exchange/forchheimer.hpp"

#include <cmath>
#include <limits>

#include "exchange/drag_law_keys.hpp"

namespace cosim::exchange {

using drag_law_keys::checked_cell_value;

double kozeny_carman_permeability(double d50, double porosity) {
  const double phi_s = 1.0 - porosity;
  if (phi_s <= 0) return std::numeric_limits<double>::infinity();
  return d50 * d50 * porosity * porosity * porosity / (150.0 * phi_s * phi_s);  // Pan et al., eq. 4
}

Forchheimer::Forchheimer(double fluid_viscosity, Basis basis, std::optional<double> value)
    : fluid_viscosity_(fluid_viscosity), basis_(basis), value_(value) {}

CellInput Forchheimer::cell_input() const {
  if (value_) return CellInput::none;
  return basis_ == Basis::grain_size ? CellInput::grain_size : CellInput::permeability;
}

double Forchheimer::coefficient(const DragInput& input) const {
  const double n = 1.0 - input.solid_fraction;
  if (n <= 0) return std::numeric_limits<double>::infinity();
  double k = 0;
  if (basis_ == Basis::permeability) {
    k = value_ ? *value_ : checked_cell_value(input.permeability, "permeability");
  } else {
    const double d50 = value_ ? *value_ : checked_cell_value(input.grain_size, "grain size");
    k = kozeny_carman_permeability(d50, n);
  }
  if (std::isinf(k)) return 0.0;
  // Pan et al. 2021, eq. 3: n^2 (mu/k + 1.75 rho_f |w| / (sqrt(150 k) n^(3/2)))
  return n * n * fluid_viscosity_ / k +
         1.75 * input.fluid_density * std::sqrt(n) * input.relative_speed / std::sqrt(150.0 * k);
}

config::Schema Forchheimer::schema() {
  config::Schema schema = drag_law_keys::base_schema(
      law,
      "Forchheimer drag, nonlinear in the relative speed (Pan et al. 2021, eq. 3), the "
      "permeability given or from the grain size D50 (eq. 4).");
  drag_law_keys::add_fluid_viscosity(schema);
  drag_law_keys::add_bed_length_scale(schema);
  return schema;
}

std::unique_ptr<DragLaw> Forchheimer::make(const config::Node& node) {
  const drag_law_keys::BedLengthScale scale = drag_law_keys::read_bed_length_scale(node);
  return std::make_unique<Forchheimer>(
      node["fluid_viscosity"].as<double>(),
      scale.from_grain_size ? Basis::grain_size : Basis::permeability, scale.value);
}

}  // namespace cosim::exchange

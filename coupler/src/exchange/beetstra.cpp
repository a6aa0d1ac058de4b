#include "exchange/beetstra.hpp"

#include <cmath>
#include <limits>

#include "exchange/drag_law_keys.hpp"

namespace cosim::exchange {

double beetstra_f0(double solid_fraction) {
  const double phi_s = solid_fraction;
  const double n = 1.0 - phi_s;
  return 10.0 * phi_s / (n * n) + n * n * (1.0 + 1.5 * std::sqrt(phi_s));  // Tran et al., eq. 28
}

double beetstra_f(double solid_fraction, double reynolds) {
  const double phi_s = solid_fraction;
  const double n = 1.0 - phi_s;
  // Tran et al., eq. 27 with numerator and denominator of the fraction
  // multiplied by Re^p, p = (1 + 4 phi_s)/2, so every power of Re is positive
  // and the correction vanishes continuously as Re -> 0.
  const double p = 0.5 * (1.0 + 4.0 * phi_s);
  const double a = 1.0 / n + 3.0 * phi_s * n;
  const double numerator =
      a * std::pow(reynolds, 1.0 + p) + 8.4 * std::pow(reynolds, 1.0 + p - 0.343);
  const double denominator = std::pow(reynolds, p) + std::pow(10.0, 3.0 * phi_s);
  return beetstra_f0(phi_s) + 0.413 / (24.0 * n * n) * numerator / denominator;
}

Beetstra::Beetstra(double fluid_viscosity, std::optional<double> grain_size)
    : fluid_viscosity_(fluid_viscosity), grain_size_(grain_size) {}

CellInput Beetstra::cell_input() const {
  return grain_size_ ? CellInput::none : CellInput::grain_size;
}

double Beetstra::coefficient(const DragInput& input) const {
  const double phi_s = input.solid_fraction;
  const double n = 1.0 - phi_s;
  if (phi_s <= 0) return 0.0;
  if (n <= 0) return std::numeric_limits<double>::infinity();
  const double mu = fluid_viscosity_;
  const double d = grain_size_ ? *grain_size_
                               : drag_law_keys::checked_cell_value(input.grain_size, "grain size");
  const double reynolds = n * input.fluid_density * d * input.relative_speed / mu;  // eq. 26
  return 18.0 * phi_s * n * mu / (d * d) * beetstra_f(phi_s, reynolds);             // eq. 25
}

config::Schema Beetstra::schema() {
  config::Schema schema = drag_law_keys::base_schema(
      law,
      "Beetstra drag, fitted to flow through sphere packings, 0.1 < phi_s < 0.6 and Re < 1000 "
      "(Tran et al., MPMICE, eqs. 25-28).");
  drag_law_keys::add_fluid_viscosity(schema);
  drag_law_keys::add_grain_size(schema);
  return schema;
}

std::unique_ptr<DragLaw> Beetstra::make(const config::Node& node) {
  return std::make_unique<Beetstra>(node["fluid_viscosity"].as<double>(),
                                    drag_law_keys::value_or_per_cell(node["grain_size"]));
}

}  // namespace cosim::exchange

#include "exchange/kozeny_carman.hpp"

#include <limits>

#include "builtin_drag_laws.hpp"

namespace cosim::exchange {

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
    const double kappa =
        value_ ? *value_ : detail::checked_cell_value(input.permeability, "permeability");
    return n * n * mu / kappa;  // Tran et al., eq. 30
  }
  if (n <= 0) return std::numeric_limits<double>::infinity();
  const double d = value_ ? *value_ : detail::checked_cell_value(input.grain_size, "grain size");
  return 180.0 * phi_s * phi_s * mu / (d * d * n);  // Tran et al., eq. 29
}

namespace detail {

std::unique_ptr<DragLaw> make_kozeny_carman(DragParameters& parameters) {
  const double mu = parameters.positive("fluid_viscosity");
  const BedLengthScale scale = read_bed_length_scale(parameters);
  return std::make_unique<KozenyCarman>(
      mu,
      scale.from_grain_size ? KozenyCarman::Basis::grain_size : KozenyCarman::Basis::permeability,
      scale.value);
}

}  // namespace detail

}  // namespace cosim::exchange

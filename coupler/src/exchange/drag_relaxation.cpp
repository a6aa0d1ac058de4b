#include "cosim/exchange/drag_relaxation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace cosim::exchange {

namespace {

void require(bool ok, const char* what, double value) {
  if (!ok) throw std::invalid_argument(fmt::format("drag relaxation: {} is {}", what, value));
}

}  // namespace

double relaxed_fraction(double rate, double exponent, double relative_speed, double dt) {
  if (std::isinf(rate)) return 1.0;
  const double decay = rate * dt;
  if (exponent == 1.0) return -std::expm1(-decay);
  // 1 - (1 + x)^(-1/(j-1)) with x = (j - 1) a |w0|^(j-1) dt; x / (1 + x) for j = 2
  if (exponent == 2.0) {
    const double x = decay * relative_speed;
    return x / (1.0 + x);
  }
  const double x = (exponent - 1.0) * decay * std::pow(relative_speed, exponent - 1.0);
  return -std::expm1(-std::log1p(x) / (exponent - 1.0));
}

void relax_drag(const DragRelaxation& cell, double dt, std::span<double> solid_velocity,
                std::span<double> fluid_velocity, std::span<double> solid_impulse) {
  const std::size_t components = solid_velocity.size();
  if (components == 0 || components > 3 || fluid_velocity.size() != components ||
      (!solid_impulse.empty() && solid_impulse.size() != components)) {
    throw std::invalid_argument(fmt::format(
        "drag relaxation: {} solid, {} fluid and {} impulse components, expected the same 1 to 3",
        components, fluid_velocity.size(), solid_impulse.size()));
  }
  require(std::isfinite(cell.solid_weight) && cell.solid_weight >= 0, "the solid weight",
          cell.solid_weight);
  require(std::isfinite(cell.fluid_weight) && cell.fluid_weight >= 0, "the fluid weight",
          cell.fluid_weight);
  require(cell.drag_coefficient >= 0, "the drag coefficient", cell.drag_coefficient);
  require(cell.exponent >= 1 && std::isfinite(cell.exponent), "the drag exponent", cell.exponent);
  require(std::isfinite(cell.virtual_mass) && cell.virtual_mass >= 0, "the virtual mass",
          cell.virtual_mass);
  require(std::isfinite(dt) && dt >= 0, "the time step", dt);
  double relative_speed_squared = 0;
  for (std::size_t k = 0; k < components; ++k) {
    require(std::isfinite(solid_velocity[k]), "a solid velocity component", solid_velocity[k]);
    require(std::isfinite(fluid_velocity[k]), "a fluid velocity component", fluid_velocity[k]);
    const double w = fluid_velocity[k] - solid_velocity[k];
    relative_speed_squared += w * w;
  }
  for (double& j : solid_impulse) j = 0.0;
  if (cell.solid_weight == 0 || cell.fluid_weight == 0 || cell.drag_coefficient == 0 || dt == 0 ||
      relative_speed_squared == 0) {
    return;
  }

  const double mu = 1.0 / cell.solid_weight + 1.0 / cell.fluid_weight;
  const double rate = std::isinf(cell.drag_coefficient)
                          ? cell.drag_coefficient
                          : cell.drag_coefficient * mu / (1.0 + cell.virtual_mass * mu);
  const double relaxed =
      relaxed_fraction(rate, cell.exponent, std::sqrt(relative_speed_squared), dt);
  const double reduced_mass = 1.0 / mu;
  for (std::size_t k = 0; k < components; ++k) {
    const double impulse = relaxed * (fluid_velocity[k] - solid_velocity[k]) * reduced_mass;
    solid_velocity[k] += impulse / cell.solid_weight;
    fluid_velocity[k] -= impulse / cell.fluid_weight;
    if (!solid_impulse.empty()) solid_impulse[k] = impulse;
  }
}

}  // namespace cosim::exchange

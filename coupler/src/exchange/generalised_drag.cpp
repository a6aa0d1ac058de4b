#include "cosim/exchange/generalised_drag.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim::exchange {

namespace {

void require(bool ok, const char* what, double value, const char* range) {
  if (!ok) {
    throw std::invalid_argument(
        fmt::format("generalised drag: {} is {}, must be {}", what, value, range));
  }
}

bool is_fraction(double value) {
  return std::isfinite(value) && value >= 0 && value <= 1;
}

bool is_positive(double value) {
  return std::isfinite(value) && value > 0;
}

// x^j, without pow for the linear and quadratic laws (every cell, every step).
double raised(double x, double j) {
  if (j == 2.0) return x * x;
  if (j == 1.0) return x;
  return std::pow(x, j);
}

}  // namespace

double DebrisMixture::confined_fraction() const {
  return solid_fraction + confined_fluid_share * fluid_fraction();
}

double DebrisMixture::free_fluid_fraction() const {
  return (1.0 - confined_fluid_share) * fluid_fraction();
}

double DebrisMixture::confined_density() const {
  const double alpha_c = confined_fraction();
  if (alpha_c <= 0) return solid_density;
  return (solid_fraction * solid_density +
          confined_fluid_share * fluid_fraction() * fluid_density) /
         alpha_c;
}

void check(const DebrisMixture& mixture) {
  require(is_fraction(mixture.solid_fraction), "the solid fraction", mixture.solid_fraction,
          "in [0, 1]");
  require(is_fraction(mixture.confined_fluid_share), "the confined fluid share",
          mixture.confined_fluid_share, "in [0, 1]");
  require(is_fraction(mixture.structured_solid_share), "the structured solid share",
          mixture.structured_solid_share, "in [0, 1]");
  require(is_positive(mixture.fluid_density), "the fluid density", mixture.fluid_density, "> 0");
  require(is_positive(mixture.fluid_viscosity), "the fluid viscosity", mixture.fluid_viscosity,
          "> 0");
  require(std::isfinite(mixture.solid_density) && mixture.solid_density > mixture.fluid_density,
          "the solid density", mixture.solid_density, "finite and above the fluid density");
}

void check(const GeneralisedDragParameters& parameters) {
  require(parameters.exponent >= 1 && parameters.exponent <= 2, "the drag exponent j",
          parameters.exponent, "in [1, 2]");
  require(parameters.reynolds_exponent >= 1 && parameters.reynolds_exponent <= 10, "the exponent M",
          parameters.reynolds_exponent, "in [1, 10]");
  require(std::isfinite(parameters.partition_exponent) && parameters.partition_exponent >= 0,
          "the partition exponent m", parameters.partition_exponent, ">= 0");
  require(is_positive(parameters.grain_size), "the grain size", parameters.grain_size, "> 0");
  require(is_positive(parameters.block_size), "the block size", parameters.block_size, "> 0");
  if (parameters.smoothing_speed) {
    require(std::isfinite(*parameters.smoothing_speed) && *parameters.smoothing_speed >= 0,
            "the smoothing speed", *parameters.smoothing_speed, ">= 0");
  }
  require(is_positive(parameters.gravity), "gravity", parameters.gravity, "> 0");
}

double settling_velocity(double grain_size, double solid_density, double fluid_density,
                         double fluid_viscosity, double gravity) {
  if (solid_density <= fluid_density) return 0.0;
  const double nu = fluid_viscosity / fluid_density;
  const double d = grain_size;
  const double x = 0.01 * (solid_density / fluid_density - 1.0) * gravity * d * d * d / (nu * nu);
  // sqrt(1 + x) - 1 without cancellation for fine grains
  return 10.0 * nu / d * (x / (std::sqrt(1.0 + x) + 1.0));
}

double virtual_mass_coefficient(const DebrisMixture& mixture) {
  return 0.5 * (1.0 + 2.0 * mixture.confined_fraction()) / mixture.free_fluid_fraction();
}

double generalised_drag_coefficient(const DebrisMixture& mixture,
                                    const GeneralisedDragParameters& parameters,
                                    std::span<const double> solid_velocity,
                                    std::span<const double> fluid_velocity) {
  if (solid_velocity.size() != fluid_velocity.size() || solid_velocity.empty() ||
      solid_velocity.size() > 3) {
    throw std::invalid_argument(fmt::format(
        "generalised drag: velocities of {} and {} components, expected the same 1 to 3",
        solid_velocity.size(), fluid_velocity.size()));
  }
  const double alpha_c = mixture.confined_fraction();
  const double alpha_u = mixture.free_fluid_fraction();
  if (alpha_c <= 0 || alpha_u <= 0) return 0.0;

  double smoothing_speed = 0;  // K, eqs. 34 and 63
  if (parameters.smoothing_speed) {
    smoothing_speed = *parameters.smoothing_speed;
  } else {
    double squared = 0;
    for (std::size_t k = 0; k < solid_velocity.size(); ++k) {
      const double mixture_velocity = alpha_c * solid_velocity[k] + alpha_u * fluid_velocity[k];
      squared += mixture_velocity * mixture_velocity;
    }
    smoothing_speed = std::sqrt(squared);
  }

  const double j = parameters.exponent;
  const double g = parameters.gravity;
  const double rho_f = mixture.fluid_density;
  const double solid_like = std::pow(alpha_u, parameters.reynolds_exponent - 1.0);  // G, eq. 64
  double coefficient = 0;

  // Structured blocks: P = 0, S_p = K / alpha_u (eqs. 61, 62).
  const double f_sc = mixture.structured_solid_share;
  const double rho_c = mixture.confined_density();
  if (f_sc > 0 && rho_c > rho_f) {
    const double u_t =
        settling_velocity(parameters.block_size, rho_c, rho_f, mixture.fluid_viscosity, g);
    const double denominator = u_t * solid_like + smoothing_speed / alpha_u;
    coefficient += f_sc * alpha_c * alpha_u * (rho_c - rho_f) * g / raised(denominator, j);
  }

  // Unconfined grains: P F + (1 - P) G (eqs. 61-64).
  if (f_sc < 1) {
    const double rho_s = mixture.solid_density;
    const double u_t =
        settling_velocity(parameters.grain_size, rho_s, rho_f, mixture.fluid_viscosity, g);
    const double partition = std::clamp(
        std::pow((1.0 - f_sc) * mixture.solid_fraction / alpha_u, parameters.partition_exponent),
        0.0, 1.0);
    const double particle_reynolds = rho_f * parameters.grain_size * u_t / mixture.fluid_viscosity;
    const double ratio = alpha_u / alpha_c;
    const double fluid_like =
        rho_f / rho_s / 180.0 * ratio * ratio * ratio * particle_reynolds;  // F
    const double smoothing = (partition / alpha_c + (1.0 - partition) / alpha_u) * smoothing_speed;
    const double denominator =
        u_t * (partition * fluid_like + (1.0 - partition) * solid_like) + smoothing;
    coefficient += (1.0 - f_sc) * alpha_c * alpha_u * (rho_s - rho_f) * g / raised(denominator, j);
  }
  return coefficient;
}

}  // namespace cosim::exchange

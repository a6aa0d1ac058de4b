#include "explicit_stability.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::cplscheme {

namespace {

// The solid solvers mark a solid held in place with this bulk density.
constexpr double held_solid_bulk_density = 1e20;
// Cells with less solid than this, or fewer pores, carry no undrained wave
// worth the name.
constexpr double negligible_fraction = 1e-6;

double smallest_width(const Mesh& mesh, std::size_t cell) {
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry)) {
    double h = std::numeric_limits<double>::infinity();
    for (int d = 0; d < grid->dim; ++d) h = std::min(h, grid->spacing[static_cast<std::size_t>(d)]);
    return h;
  }
  return std::pow(mesh.control_volume(cell), 1.0 / mesh.dimension());
}

}  // namespace

ExplicitStabilityBound undrained_wave_bound(const Mesh& mesh,
                                            std::span<const double> solid_fraction,
                                            std::span<const double> solid_bulk_density,
                                            std::span<const double> fluid_bulk_density,
                                            std::span<const double> fluid_bulk_modulus) {
  ExplicitStabilityBound bound;
  for (std::size_t c = 0; c < solid_fraction.size(); ++c) {
    const double n = 1.0 - solid_fraction[c];
    if (solid_fraction[c] < negligible_fraction || n < negligible_fraction) continue;
    if (solid_bulk_density[c] > held_solid_bulk_density) continue;
    const double mass = fluid_bulk_density[c] + solid_bulk_density[c];
    if (!(fluid_bulk_modulus[c] > 0.0) || !(mass > 0.0)) continue;
    const double speed = std::sqrt(fluid_bulk_modulus[c] / (n * mass));
    const double h = smallest_width(mesh, c);
    if (h / speed < bound.window) bound = {h / speed, speed, h, n, c};
  }
  return bound;
}

}  // namespace cosim::cplscheme

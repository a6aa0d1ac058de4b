#include "mpm/coupling/porous_fields_writer.hpp"

#include <algorithm>

namespace mpm::coupling {

template <int Dim>
PorousFields porous_fields(const ExchangeGrid<Dim>& grid, const Particles<Dim>& particles,
                           const std::vector<BodyRole>& roles, const std::vector<std::uint8_t>& held,
                           double held_density_factor) {
  const std::size_t n = grid.size();
  const auto dim = static_cast<std::size_t>(Dim);
  PorousFields out;
  out.solid_fraction.assign(n, 0.0);
  out.solid_velocity.assign(n * dim, 0.0);
  out.solid_bulk_density.assign(n, 0.0);
  out.permeability.assign(n, 0.0);
  out.grain_size.assign(n, 0.0);
  out.held.assign(n, 0);
  std::vector<double> volume_velocity(n * dim, 0.0), volume(n, 0.0), porous_mass(n, 0.0);
  std::vector<double> held_mass(n, 0.0), held_volume(n, 0.0);

  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double m = particles.mass[p];
    const double solid_volume = (1.0 - particles.porosity[p]) * particles.volume[p];
    const bool porous = roles[particles.body[p]].porous;
    const Vec<Dim>& v = particles.velocity[p];
    grid.for_each_conservative(particles.position[p], particles.half_length[p], [&](std::size_t c, double w) {
      out.solid_fraction[c] += w * solid_volume;
      out.solid_bulk_density[c] += w * m;
      volume[c] += w * solid_volume;
      for (std::size_t k = 0; k < dim; ++k) {
        out.solid_velocity[c * dim + k] += w * m * v[static_cast<int>(k)];
        volume_velocity[c * dim + k] += w * solid_volume * v[static_cast<int>(k)];
      }
      if (porous) {
        porous_mass[c] += w * m;
        out.permeability[c] += w * m * particles.permeability[p];
        out.grain_size[c] += w * m * particles.grain_size[p];
      }
      if (held[p]) {
        held_mass[c] += w * m;
        held_volume[c] += w * solid_volume;
      }
    });
  }

  const double cell_volume = grid.cell_volume();
  for (std::size_t c = 0; c < n; ++c) {
    const double mass = out.solid_bulk_density[c];
    for (std::size_t k = 0; k < dim; ++k) {
      double& u = out.solid_velocity[c * dim + k];
      u = mass > 0.0 ? u / mass : volume[c] > 0.0 ? volume_velocity[c * dim + k] / volume[c] : 0.0;
    }
    if (porous_mass[c] > 0.0) {
      out.permeability[c] /= porous_mass[c];
      out.grain_size[c] /= porous_mass[c];
    }
    double& phi = out.solid_fraction[c];
    phi /= cell_volume;
    if (phi > 1.0) {
      phi = 1.0;
      ++out.capped_cells;
    }
    double& rho = out.solid_bulk_density[c];
    rho /= cell_volume;
    const bool held_cell = mass > 0.0 ? 2.0 * held_mass[c] > mass : 2.0 * held_volume[c] > volume[c];
    if (held_cell) {
      out.held[c] = 1;
      rho = held_density_factor * std::max(rho, 1.0);
    }
  }
  return out;
}

template PorousFields porous_fields<2>(const ExchangeGrid<2>&, const Particles<2>&, const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double);
template PorousFields porous_fields<3>(const ExchangeGrid<3>&, const Particles<3>&, const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double);

}  // namespace mpm::coupling

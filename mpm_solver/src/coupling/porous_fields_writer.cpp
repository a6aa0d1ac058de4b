#include "mpm/coupling/porous_fields_writer.hpp"

#include <algorithm>
#include <array>

namespace mpm::coupling {

namespace {

// A cell whose solid is mostly held counts as held while the solid not held fills at most this
// fraction of it (the tips of domains of a deformable body resting on a rigid one).
constexpr double max_free_fraction_of_held_cell = 0.1;

}  // namespace

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
  std::vector<double> held_mass(n, 0.0), held_volume(n, 0.0), held_momentum(n * dim, 0.0);

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
        for (std::size_t k = 0; k < dim; ++k)
          held_momentum[c * dim + k] += w * m * v[static_cast<int>(k)];
      }
    });
  }

  const double cell_volume = grid.cell_volume();
  for (std::size_t c = 0; c < n; ++c) {
    const double mass = out.solid_bulk_density[c];
    // The solid not held (a deformable body's points) in the cell: its mass, momentum and volume.
    const double free_mass = mass - held_mass[c];
    const double free_volume = volume[c] - held_volume[c];
    std::array<double, 3> free_momentum{};
    for (std::size_t k = 0; k < dim; ++k)
      free_momentum[k] = out.solid_velocity[c * dim + k] - held_momentum[c * dim + k];
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
      // Not counted: the round-off of a cell its domains fill exactly.
      if (phi > 1.0 + 1e-9) ++out.capped_cells;
      phi = 1.0;
    }
    double& rho = out.solid_bulk_density[c];
    rho /= cell_volume;
    // Held: most of the solid mass is held and the rest fills at most a tenth of the cell.
    const bool mostly_held =
        mass > 0.0 ? 2.0 * held_mass[c] > mass : 2.0 * held_volume[c] > volume[c];
    const bool held_cell =
        mostly_held && free_volume <= max_free_fraction_of_held_cell * cell_volume;
    if (held_cell) {
      out.held[c] = 1;
      rho = held_density_factor * std::max(rho, 1.0);
      // A held cell moves with its held solid alone: the tips of a deformable body's domains
      // reaching into it (sand on a rigid bed) would give the held solid their velocity, and with
      // it the fluid the impermeable drag ties to it, straining the fluid's held pores.
      if (held_mass[c] > 0.0) {
        for (std::size_t k = 0; k < dim; ++k)
          out.solid_velocity[c * dim + k] = held_momentum[c * dim + k] / held_mass[c];
      }
    } else if (held_mass[c] > 0.0 && free_mass > 0.0) {
      // A cell a rigid bed shares with a deformable body sliding over it moves with the deformable
      // body: the fluid in its pores goes with it, the bed's part of the cell only takes pore space
      // (its solid volume counts in phi_s).
      for (std::size_t k = 0; k < dim; ++k)
        out.solid_velocity[c * dim + k] = free_momentum[k] / free_mass;
    }
  }
  return out;
}

template PorousFields porous_fields<2>(const ExchangeGrid<2>&, const Particles<2>&, const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double);
template PorousFields porous_fields<3>(const ExchangeGrid<3>&, const Particles<3>&, const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double);

}  // namespace mpm::coupling

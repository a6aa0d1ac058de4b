#include "mpm/coupling/porous_fields_writer.hpp"

#include <algorithm>

#include "mpm/coupling/cell_solid_sums.hpp"

namespace mpm::coupling {

namespace {

// A cell whose solid is mostly held counts as held while the solid not held fills at most this
// fraction of it (the tips of domains of a deformable body resting on a rigid one).
constexpr double max_free_fraction_of_held_cell = 0.1;

}  // namespace

template <int Dim>
PorousFields porous_fields(const ExchangeGrid<Dim>& grid, const Particles<Dim>& particles,
                           const std::vector<BodyRole>& roles,
                           const std::vector<std::uint8_t>& held, double held_density_factor,
                           const SumOverRanks& sum_over_ranks) {
  const std::size_t n = grid.size();
  const auto dim = static_cast<std::size_t>(Dim);
  CellSolidSums free(n, Dim), held_sums(n, Dim);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    CellSolidSums& sums = held[p] ? held_sums : free;
    const double m = particles.mass[p];
    const double solid_volume = (1.0 - particles.porosity[p]) * particles.volume[p];
    const bool porous = roles[particles.body[p]].porous;
    const Vec<Dim>& v = particles.velocity[p];
    grid.for_each_conservative(
        particles.position[p], particles.half_length[p], [&](std::size_t c, double w) {
          sums.domain[c] += w * particles.volume[p];
          sums.solid_volume[c] += w * solid_volume;
          sums.mass[c] += w * m;
          for (std::size_t k = 0; k < dim; ++k) {
            sums.momentum[c * dim + k] += w * m * v[static_cast<int>(k)];
            sums.volume_momentum[c * dim + k] += w * solid_volume * v[static_cast<int>(k)];
          }
          if (porous) {
            sums.porous_mass[c] += w * m;
            sums.permeability_mass[c] += w * m * particles.permeability[p];
            sums.grain_size_mass[c] += w * m * particles.grain_size[p];
          }
        });
  }
  if (sum_over_ranks) sum_cells_over_ranks(free, held_sums, sum_over_ranks);
  PorousFields out;
  out.overfilled_cells = spread_overfilled_cells(grid, free, held_sums);

  out.solid_fraction.assign(n, 0.0);
  out.solid_velocity.assign(n * dim, 0.0);
  out.solid_volume_flux.assign(n * dim, 0.0);
  out.solid_bulk_density.assign(n, 0.0);
  out.permeability.assign(n, 0.0);
  out.grain_size.assign(n, 0.0);
  out.held.assign(n, 0);
  const double cell_volume = grid.cell_volume();
  for (std::size_t c = 0; c < n; ++c) {
    const double free_mass = free.mass[c];
    const double held_mass = held_sums.mass[c];
    const double mass = free_mass + held_mass;
    const double free_volume = free.solid_volume[c];
    const double volume = free_volume + held_sums.solid_volume[c];
    for (std::size_t k = 0; k < dim; ++k) {
      const std::size_t i = c * dim + k;
      out.solid_velocity[i] =
          mass > 0.0     ? (free.momentum[i] + held_sums.momentum[i]) / mass
          : volume > 0.0 ? (free.volume_momentum[i] + held_sums.volume_momentum[i]) / volume
                         : 0.0;
    }
    const double porous_mass = free.porous_mass[c] + held_sums.porous_mass[c];
    if (porous_mass > 0.0) {
      out.permeability[c] =
          (free.permeability_mass[c] + held_sums.permeability_mass[c]) / porous_mass;
      out.grain_size[c] = (free.grain_size_mass[c] + held_sums.grain_size_mass[c]) / porous_mass;
    }
    double& phi = out.solid_fraction[c];
    phi = volume / cell_volume;
    // Capped with phi below: the flux of the solid the cell holds.
    const double held_share = phi > 1.0 ? 1.0 / phi : 1.0;
    for (std::size_t k = 0; k < dim; ++k) {
      const std::size_t i = c * dim + k;
      out.solid_volume_flux[i] =
          held_share * (free.volume_momentum[i] + held_sums.volume_momentum[i]) / cell_volume;
    }
    if (phi > 1.0) {
      // Not counted: the overfill the spreading leaves (0.1 % of the cell at most, and round-off).
      if (phi > 1.0 + 1e-3) ++out.capped_cells;
      phi = 1.0;
    }
    double& rho = out.solid_bulk_density[c];
    rho = mass / cell_volume;
    // Held: most of the solid mass is held and the rest fills at most a tenth of the cell.
    const bool mostly_held =
        mass > 0.0 ? 2.0 * held_mass > mass : 2.0 * held_sums.solid_volume[c] > volume;
    const bool held_cell =
        mostly_held && free_volume <= max_free_fraction_of_held_cell * cell_volume;
    if (held_cell) {
      out.held[c] = 1;
      rho = held_density_factor * std::max(rho, 1.0);
      // A held cell moves with its held solid alone: the tips of a deformable body's domains
      // reaching into it (sand on a rigid bed) would give the held solid their velocity, and with
      // it the fluid the impermeable drag ties to it, straining the fluid's held pores.
      if (held_mass > 0.0) {
        for (std::size_t k = 0; k < dim; ++k)
          out.solid_velocity[c * dim + k] = held_sums.momentum[c * dim + k] / held_mass;
      }
    } else if (held_mass > 0.0 && free_mass > 0.0) {
      // A cell a rigid bed shares with a deformable body sliding over it moves with the deformable
      // body: the fluid in its pores goes with it, the bed's part of the cell only takes pore space
      // (its solid volume counts in phi_s).
      for (std::size_t k = 0; k < dim; ++k)
        out.solid_velocity[c * dim + k] = free.momentum[c * dim + k] / free_mass;
    }
  }
  return out;
}

template PorousFields porous_fields<2>(const ExchangeGrid<2>&, const Particles<2>&,
                                       const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double,
                                       const SumOverRanks&);
template PorousFields porous_fields<3>(const ExchangeGrid<3>&, const Particles<3>&,
                                       const std::vector<BodyRole>&,
                                       const std::vector<std::uint8_t>&, double,
                                       const SumOverRanks&);

}  // namespace mpm::coupling

#include "mpm/coupling/momentum_exchange_increment.hpp"

#include <array>
#include <cmath>

namespace mpm::coupling {

template <int Dim>
ImpulseSplit<Dim> split_impulse(const ExchangeGrid<Dim>& grid, std::span<const double> cell_impulse,
                                const Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                                std::vector<Vec<Dim>>& particle_impulse, SplitWeight weighting) {
  const std::size_t n = grid.size();
  const auto dim = static_cast<std::size_t>(Dim);
  const bool by_volume = weighting == SplitWeight::solid_volume;
  // Each particle's weight: its mass, or its solid volume.
  const auto weight_of = [&](std::size_t p) {
    return by_volume ? (1.0 - particles.porosity[p]) * particles.volume[p] : particles.mass[p];
  };
  // `mass` is the deformable particles' weight in a cell, `rigid_mass` the rigid ones'.
  std::vector<double> mass(n, 0.0), rigid_mass(n, 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const bool rigid = roles[particles.body[p]].rigid;
    const double m = weight_of(p);
    grid.for_each_conservative(particles.position[p], particles.half_length[p], [&](std::size_t c, double w) {
      (rigid ? rigid_mass : mass)[c] += w * m;
    });
  }
  std::vector<Vec<Dim>> impulse(n);
  for (std::size_t c = 0; c < n; ++c) impulse[c] = Eigen::Map<const Vec<Dim>>(cell_impulse.data() + c * dim);
  ImpulseSplit<Dim> split;
  for (const auto& j : impulse) split.received += j;
  // An impulse in a cell without any solid is a smear of the coupler's
  // mappings next to the solid's edge: it goes to the neighbouring cells
  // (3^Dim block) by their deformable mass, so it is not lost.
  for (std::size_t c = 0; c < n; ++c) {
    if (mass[c] > 0.0 || rigid_mass[c] > 0.0 || impulse[c].isZero(0.0)) continue;
    std::array<int, Dim> centre{};
    std::size_t rest = c;
    for (std::size_t d = 0; d < dim; ++d) {
      centre[d] = static_cast<int>(rest % static_cast<std::size_t>(grid.cells[d]));
      rest /= static_cast<std::size_t>(grid.cells[d]);
    }
    std::vector<std::size_t> neighbours;
    double neighbour_mass = 0.0;
    for (int k = 0; k < static_cast<int>(std::pow(3, Dim)); ++k) {
      std::array<int, Dim> index{};
      bool inside = true;
      for (std::size_t d = 0, code = static_cast<std::size_t>(k); d < dim; ++d, code /= 3) {
        index[d] = centre[d] + static_cast<int>(code % 3) - 1;
        inside = inside && index[d] >= 0 && index[d] < grid.cells[d];
      }
      if (!inside) continue;
      const std::size_t f = grid.flat(index);
      if (mass[f] > 0.0) {
        neighbours.push_back(f);
        neighbour_mass += mass[f];
      }
    }
    if (neighbours.empty()) continue;
    const Vec<Dim> moved = impulse[c];
    for (std::size_t f : neighbours) impulse[f] += moved * (mass[f] / neighbour_mass);
    impulse[c].setZero();
  }
  // Impulse per unit of weight in each cell (by volume the rigid solid's
  // share is absorbed).
  std::vector<Vec<Dim>> per_mass(n, Vec<Dim>::Zero());
  for (std::size_t c = 0; c < n; ++c) {
    const double total = by_volume ? mass[c] + rigid_mass[c] : mass[c];
    if (mass[c] > 0.0) {
      per_mass[c] = impulse[c] / total;
      if (by_volume) split.absorbed += impulse[c] * (rigid_mass[c] / total);
    } else {
      split.absorbed += impulse[c];
    }
  }
  particle_impulse.assign(particles.size(), Vec<Dim>::Zero());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (roles[particles.body[p]].rigid) continue;
    const double m = weight_of(p);
    Vec<Dim>& j = particle_impulse[p];
    grid.for_each_conservative(particles.position[p], particles.half_length[p], [&](std::size_t c, double w) { j += (w * m) * per_mass[c]; });
    split.applied += j;
  }
  return split;
}

template ImpulseSplit<2> split_impulse<2>(const ExchangeGrid<2>&, std::span<const double>,
                                          const Particles<2>&, const std::vector<BodyRole>&,
                                          std::vector<Vec<2>>&, SplitWeight);
template ImpulseSplit<3> split_impulse<3>(const ExchangeGrid<3>&, std::span<const double>,
                                          const Particles<3>&, const std::vector<BodyRole>&,
                                          std::vector<Vec<3>>&, SplitWeight);

}  // namespace mpm::coupling

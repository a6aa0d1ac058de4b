#include "mpm/coupling/momentum_exchange_increment.hpp"

namespace mpm::coupling {

template <int Dim>
ImpulseSplit<Dim> split_impulse(const ExchangeGrid<Dim>& grid, std::span<const double> cell_impulse,
                                const Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                                std::vector<Vec<Dim>>& particle_impulse) {
  const std::size_t n = grid.size();
  const auto dim = static_cast<std::size_t>(Dim);
  std::vector<double> mass(n, 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (roles[particles.body[p]].rigid) continue;
    const double m = particles.mass[p];
    grid.for_each_conservative(particles.position[p], [&](std::size_t c, double w) { mass[c] += w * m; });
  }
  // Impulse per unit of mass weight in each cell.
  std::vector<Vec<Dim>> per_mass(n, Vec<Dim>::Zero());
  ImpulseSplit<Dim> split;
  for (std::size_t c = 0; c < n; ++c) {
    const Vec<Dim> j = Eigen::Map<const Vec<Dim>>(cell_impulse.data() + c * dim);
    split.received += j;
    if (mass[c] > 0.0)
      per_mass[c] = j / mass[c];
    else
      split.absorbed += j;
  }
  particle_impulse.assign(particles.size(), Vec<Dim>::Zero());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (roles[particles.body[p]].rigid) continue;
    const double m = particles.mass[p];
    Vec<Dim>& j = particle_impulse[p];
    grid.for_each_conservative(particles.position[p], [&](std::size_t c, double w) { j += (w * m) * per_mass[c]; });
    split.applied += j;
  }
  return split;
}

template ImpulseSplit<2> split_impulse<2>(const ExchangeGrid<2>&, std::span<const double>, const Particles<2>&,
                                          const std::vector<BodyRole>&, std::vector<Vec<2>>&);
template ImpulseSplit<3> split_impulse<3>(const ExchangeGrid<3>&, std::span<const double>, const Particles<3>&,
                                          const std::vector<BodyRole>&, std::vector<Vec<3>>&);

}  // namespace mpm::coupling

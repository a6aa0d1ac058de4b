#include "mpm/coupling/momentum_exchange_increment.hpp"

namespace mpm::coupling {

template <int Dim>
ImpulseSplit<Dim> split_impulse(const ExchangeGrid<Dim>& grid, std::span<const double> cell_impulse,
                                const Particles<Dim>& particles, const std::vector<BodyRole>& roles,
                                std::vector<Vec<Dim>>& particle_impulse, SplitWeight weighting,
                                const SumOverRanks& sum_over_ranks) {
  const bool by_volume = weighting == SplitWeight::solid_volume;
  std::vector<double> deformable(particles.size(), 0.0), rigid(particles.size(), 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double weight =
        by_volume ? (1.0 - particles.porosity[p]) * particles.volume[p] : particles.mass[p];
    (roles[particles.body[p]].rigid ? rigid : deformable)[p] = weight;
  }
  return share_over_particles<Dim, Dim>(grid, cell_impulse, particles, deformable, rigid,
                                        particle_impulse, by_volume, sum_over_ranks);
}

template ImpulseSplit<2> split_impulse<2>(const ExchangeGrid<2>&, std::span<const double>,
                                          const Particles<2>&, const std::vector<BodyRole>&,
                                          std::vector<Vec<2>>&, SplitWeight, const SumOverRanks&);
template ImpulseSplit<3> split_impulse<3>(const ExchangeGrid<3>&, std::span<const double>,
                                          const Particles<3>&, const std::vector<BodyRole>&,
                                          std::vector<Vec<3>>&, SplitWeight, const SumOverRanks&);

}  // namespace mpm::coupling

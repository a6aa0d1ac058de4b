#include "mpm/coupling/heat_exchange_increment.hpp"

#include "mpm/coupling/share_over_particles.hpp"

namespace mpm::coupling {

template <int Dim>
HeatSplit split_heat(const ExchangeGrid<Dim>& grid, std::span<const double> cell_heat,
                     const Particles<Dim>& particles, std::vector<double>& particle_heat,
                     const SumOverRanks& sum_over_ranks) {
  std::vector<Eigen::Matrix<double, 1, 1>> shares;
  const auto totals = share_over_particles<Dim, 1>(
      grid, cell_heat, particles, particles.heat_capacity, {}, shares, false, sum_over_ranks);
  particle_heat.resize(shares.size());
  for (std::size_t p = 0; p < shares.size(); ++p) particle_heat[p] = shares[p][0];
  return {totals.received[0], totals.applied[0], totals.absorbed[0]};
}

template HeatSplit split_heat<2>(const ExchangeGrid<2>&, std::span<const double>,
                                 const Particles<2>&, std::vector<double>&, const SumOverRanks&);
template HeatSplit split_heat<3>(const ExchangeGrid<3>&, std::span<const double>,
                                 const Particles<3>&, std::vector<double>&, const SumOverRanks&);

}  // namespace mpm::coupling

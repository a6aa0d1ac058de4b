#include "mpm/coupling/thermal_fields_writer.hpp"

namespace mpm::coupling {

template <int Dim>
ThermalFields thermal_fields(const ExchangeGrid<Dim>& grid, const Particles<Dim>& particles,
                             const SumOverRanks& sum_over_ranks) {
  const std::size_t n = grid.size();
  std::vector<double> capacity(n, 0.0), energy(n, 0.0);
  double total_capacity = 0.0, total_energy = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double C = particles.heat_capacity[p];
    if (C <= 0.0) continue;
    const double CT = C * particles.temperature[p];
    total_capacity += C;
    total_energy += CT;
    grid.for_each_conservative(particles.position[p], particles.half_length[p],
                               [&](std::size_t c, double w) {
                                 capacity[c] += w * C;
                                 energy[c] += w * CT;
                               });
  }
  if (sum_over_ranks) {
    std::vector<double> packed(capacity);
    packed.insert(packed.end(), energy.begin(), energy.end());
    packed.insert(packed.end(), {total_capacity, total_energy});
    sum_over_ranks(packed);
    std::copy(packed.begin(), packed.begin() + static_cast<std::ptrdiff_t>(n), capacity.begin());
    std::copy(packed.begin() + static_cast<std::ptrdiff_t>(n),
              packed.begin() + static_cast<std::ptrdiff_t>(2 * n), energy.begin());
    total_capacity = packed[2 * n];
    total_energy = packed[2 * n + 1];
  }
  const double solid_mean = total_capacity > 0.0 ? total_energy / total_capacity : 0.0;
  ThermalFields out;
  out.solid_temperature.assign(n, solid_mean);
  out.solid_heat_capacity.assign(n, 0.0);
  const double cell_volume = grid.cell_volume();
  for (std::size_t c = 0; c < n; ++c) {
    out.solid_heat_capacity[c] = capacity[c] / cell_volume;
    if (capacity[c] > 0.0) {
      out.solid_temperature[c] = energy[c] / capacity[c];
      continue;
    }
    double around_capacity = 0.0, around_energy = 0.0;
    grid.for_each_neighbour(c, [&](std::size_t f) {
      around_capacity += capacity[f];
      around_energy += energy[f];
    });
    if (around_capacity > 0.0) out.solid_temperature[c] = around_energy / around_capacity;
  }
  return out;
}

template ThermalFields thermal_fields<2>(const ExchangeGrid<2>&, const Particles<2>&,
                                         const SumOverRanks&);
template ThermalFields thermal_fields<3>(const ExchangeGrid<3>&, const Particles<3>&,
                                         const SumOverRanks&);

}  // namespace mpm::coupling

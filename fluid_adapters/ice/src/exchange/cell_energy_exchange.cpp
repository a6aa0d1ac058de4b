#include <array>
#include <span>

#include "cosim/exchange/implicit_exchange.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// Tran et al., MPMICE, eqs. 69-70: implicit heat exchange of the Lagrangian
// temperatures, with H_ij phi_i phi_j.
template <int Dim>
void IceSolver<Dim>::exchange_cell_energy(double dt) {
  const std::size_t n = count();
  const bool heat = n >= 2 && has_heat_exchange_;
  std::array<double, cosim::exchange::kMaxMaterials> weight{};
  std::array<double, cosim::exchange::kMaxMaterials> specific_heat{};
  std::array<double, cosim::exchange::kMaxMaterials> value{};
  std::array<double, cosim::exchange::kMaxMaterials> increment{};
  std::array<double, cosim::exchange::kMaxMaterials * cosim::exchange::kMaxMaterials> coefficient{};
  for (std::size_t m = 0; m < n; ++m) specific_heat[m] = eos_[m]->specific_heat();
  for (std::size_t c = 0; c < at(grid_.cell_count()); ++c) {
    for (std::size_t m = 0; m < n; ++m) weight[m] = mass_[m][c];
    for (std::size_t m = 0; m < n; ++m) {
      lagrangian_temperature_[m][c] = energy_[m][c] / (mass_[m][c] * specific_heat[m]);
    }
    if (heat) {
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
          coefficient[i * n + j] = exchange_.heat[i * n + j] *
                                   state_.materials[i].volume_fraction[c] *
                                   state_.materials[j].volume_fraction[c];
        }
        value[i] = lagrangian_temperature_[i][c];
      }
      cosim::exchange::exchange_energy(std::span<const double>(weight.data(), n),
                                       std::span<const double>(specific_heat.data(), n),
                                       std::span<const double>(value.data(), n),
                                       std::span<const double>(coefficient.data(), n * n), dt,
                                       std::span<double>(increment.data(), n));
      for (std::size_t m = 0; m < n; ++m) {
        lagrangian_temperature_[m][c] += increment[m];
        energy_[m][c] = mass_[m][c] * specific_heat[m] * lagrangian_temperature_[m][c];
      }
    }
  }
}

template void IceSolver<1>::exchange_cell_energy(double);
template void IceSolver<2>::exchange_cell_energy(double);
template void IceSolver<3>::exchange_cell_energy(double);

}  // namespace ice

#include <array>
#include <span>

#include "cosim/exchange/implicit_exchange.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// Tran et al., MPMICE, eqs. 67-68: implicit momentum exchange of the
// Lagrangian cell velocities, with K_ij phi_i phi_j (eqs. 69-70 do the same
// for the temperatures, exchange_cell_energy). With the drag solved here
// the solid takes part as at the faces (weight rhobar_s, K phi_f / n to each
// fluid); its velocity and the impulse it has received keep the increment.
template <int Dim>
void IceSolver<Dim>::exchange_cell_momentum(double dt) {
  const std::size_t n = count();
  const bool drag = solid_drag_on_;
  const bool fluid_exchange = n >= 2 && has_momentum_exchange_;
  if (!fluid_exchange && !drag) return;
  if (n == 2 && !drag) {
    // Two fluids: eq. 131's closed form per cell (as solve_implicit_exchange forms it).
    const double k = exchange_.momentum[1];
    const double* phi_0 = state_.materials[0].volume_fraction.data();
    const double* phi_1 = state_.materials[1].volume_fraction.data();
    for (std::size_t c = 0; c < at(grid_.cell_count()); ++c) {
      const double w_0 = mass_[0][c], w_1 = mass_[1][c];
      const double dt_c = dt * (k * phi_0[c] * phi_1[c]);
      if (!(w_0 > 0.0 && w_1 > 0.0 && dt_c > 0.0)) continue;
      const double resistance = 1.0 / dt_c + 1.0 / w_0 + 1.0 / w_1;
      for (int d = 0; d < Dim; ++d) {
        double& p_0 = momentum_[0][at(d)][c];
        double& p_1 = momentum_[1][at(d)][c];
        const double impulse = (p_1 / w_1 - p_0 / w_0) / resistance;
        p_0 += w_0 * (impulse / w_0);
        p_1 += w_1 * (-impulse / w_1);
      }
    }
    return;
  }
  const std::size_t solid = n;
  const std::size_t total = drag ? n + 1 : n;
  std::array<double, cosim::exchange::kMaxMaterials> weight{};
  std::array<double, cosim::exchange::kMaxMaterials * 3> value{};
  std::array<double, cosim::exchange::kMaxMaterials * 3> increment{};
  std::array<double, cosim::exchange::kMaxMaterials * cosim::exchange::kMaxMaterials> coefficient{};
  const auto dim = static_cast<std::size_t>(Dim);
  const double volume = grid_.cell_volume();
  for (std::size_t c = 0; c < at(grid_.cell_count()); ++c) {
    for (std::size_t m = 0; m < n; ++m) weight[m] = mass_[m][c];
    for (std::size_t i = 0; i < total * total; ++i) coefficient[i] = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (fluid_exchange) {
        for (std::size_t j = 0; j < n; ++j) {
          coefficient[i * total + j] = exchange_.momentum[i * n + j] *
                                       state_.materials[i].volume_fraction[c] *
                                       state_.materials[j].volume_fraction[c];
        }
      }
      for (std::size_t d = 0; d < dim; ++d) value[i * dim + d] = momentum_[i][d][c] / mass_[i][c];
    }
    if (drag) {
      weight[solid] = solid_bulk_density_[c];
      for (std::size_t m = 0; m < n; ++m) {
        coefficient[m * total + solid] = solid_drag_[c] * drag_share_[m] *
                                         state_.materials[m].volume_fraction[c] /
                                         state_.porosity[c];
      }
      for (std::size_t d = 0; d < dim; ++d) value[solid * dim + d] = solid_exchange_velocity_[d][c];
    }
    cosim::exchange::solve_implicit_exchange(
        std::span<const double>(weight.data(), total),
        std::span<const double>(value.data(), total * dim), Dim,
        std::span<const double>(coefficient.data(), total * total), dt,
        std::span<double>(increment.data(), total * dim));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t d = 0; d < dim; ++d)
        momentum_[i][d][c] += mass_[i][c] * increment[i * dim + d];
    }
    if (drag) {
      for (std::size_t d = 0; d < dim; ++d) {
        const double du = increment[solid * dim + d];
        solid_exchange_velocity_[d][c] += du;
        solid_impulse_[c * dim + d] += solid_bulk_density_[c] * du * volume;
      }
    }
  }
}

template void IceSolver<1>::exchange_cell_momentum(double);
template void IceSolver<2>::exchange_cell_momentum(double);
template void IceSolver<3>::exchange_cell_momentum(double);

}  // namespace ice

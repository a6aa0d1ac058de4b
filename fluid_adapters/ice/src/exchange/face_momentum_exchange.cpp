#include <array>
#include <limits>
#include <span>

#include "cosim/exchange/implicit_exchange.hpp"
#include "ice/grid/face_walk.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

namespace {

// Eq. 131's closed form for two fluids on the interior faces
// first <= f < end of a row (upper cell f - upper_offset, lower one stride
// below), see exchange_two_fluid_faces. A function of its own, with
// restrict-qualified outputs and branch-free, so that the loop vectorises:
// a face without exchange (no coefficient, or a material without mass,
// which the state excludes) adds 0 times its increments.
inline void interior_two_fluid_exchange(int first, int end, int upper_offset, int stride, double dt,
                                        double k, const double* __restrict rhobar_0,
                                        const double* __restrict rhobar_1,
                                        const double* __restrict phi_0,
                                        const double* __restrict phi_1, double* __restrict u_0,
                                        double* __restrict u_1, double* __restrict y_0,
                                        double* __restrict y_1) {
  for (int f = first; f < end; ++f) {
    const int upper = f - upper_offset;
    const int lower = upper - stride;
    const double w_0 = 0.5 * (rhobar_0[lower] + rhobar_0[upper]);
    const double w_1 = 0.5 * (rhobar_1[lower] + rhobar_1[upper]);
    const double fraction_0 = 0.5 * (phi_0[lower] + phi_0[upper]);
    const double fraction_1 = 0.5 * (phi_1[lower] + phi_1[upper]);
    const double dt_c = dt * (k * fraction_0 * fraction_1);
    const double exchanged = (w_0 > 0.0) & (w_1 > 0.0) & (dt_c > 0.0) ? 1.0 : 0.0;
    const double resistance = 1.0 / dt_c + 1.0 / w_0 + 1.0 / w_1;
    const double impulse = (u_1[f] - u_0[f]) / resistance;
    const double correction = (y_1[f] - y_0[f]) / resistance;
    u_0[f] += exchanged * (impulse / w_0);
    u_1[f] += exchanged * (-impulse / w_1);
    y_0[f] += exchanged * (correction / w_0);
    y_1[f] += exchanged * (-correction / w_1);
  }
}

}  // namespace

// Tran et al., MPMICE, eq. 48 and appendix eqs. 126-131: the implicit
// exchange of the predicted face velocities, and the same exchange applied
// to the pressure correction. Each material's correction is
// rhobar_f dU_f = -dt phi_f grad dP + dt sum_j K_fj (dU_j - dU_f), so
// dU = -dt y grad dP with (W + dt L) y = W v_FC; the pressure equation then
// sees the face coefficient 1 / rho_FC = sum_f phi_f,FC y_f, which is
// sum_f phi_f / rho_f without exchange and 1 / rho_mixture when K -> inf,
// and the corrected face velocities satisfy both the exchange and the
// volume balance at the new time level.
//
// A coupled porous solid adds its volume flux phi_s U_s to the divergence
// (eq. 75's mixture velocity), taken from the upwind cell (no solid flows
// out of a cell that has none, nor in through a side of the domain). With
// the drag solved here it is one more material of the exchange, with weight
// rhobar_s, coefficient K phi_f / n to each fluid and no pressure term of
// its own (v_s = 0: its share -phi_s grad P acts in the solid solver), so
// y_s > 0 only through the drag: where K is large the pressure pushes fluid
// and solid together, and the pressure equation is that of Darcy flow.
template <int Dim>
void IceSolver<Dim>::exchange_face_momentum(double dt) {
  const std::size_t n = count();
  const bool drag = solid_drag_on_;
  const std::size_t solid = n;  // the solid's index in the exchange
  const std::size_t total = drag ? n + 1 : n;
  std::array<double, cosim::exchange::kMaxMaterials> weight{};
  std::array<double, cosim::exchange::kMaxMaterials> fraction{};
  std::array<double, cosim::exchange::kMaxMaterials> value{};
  std::array<double, cosim::exchange::kMaxMaterials> increment{};
  std::array<double, cosim::exchange::kMaxMaterials * cosim::exchange::kMaxMaterials> coefficient{};
  const std::span<double> w(weight.data(), total);
  const std::span<double> x(value.data(), total);
  const std::span<double> dx(increment.data(), total);
  const std::span<double> k(coefficient.data(), total * total);
  const bool fluid_exchange = n >= 2 && has_momentum_exchange_;
  if (fluid_exchange && n == 2 && !drag) {
    exchange_two_fluid_faces(dt);
    return;
  }

  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid_.face_count(d); ++f) {
      const int lower = grid_.lower_cell(d, f);
      const int upper = grid_.upper_cell(d, f);
      const bool interior = lower >= 0 && upper >= 0;
      const bool upper_side = upper < 0;
      const int cell = upper_side ? lower : upper;
      const SideType type =
          interior ? SideType::fixed_pressure : sides_[at(2 * d + (upper_side ? 1 : 0))].type;
      const auto face_value = [&](const CellField& field) {
        return interior ? 0.5 * (field[at(lower)] + field[at(upper)]) : field[at(cell)];
      };
      for (std::size_t m = 0; m < n; ++m) {
        weight[m] = face_value(state_.materials[m].bulk_density);
        fraction[m] = face_value(state_.materials[m].volume_fraction);
      }
      double& u_s = solid_face_velocity_[at(d)][at(f)];
      double& phi_s = solid_face_fraction_[at(d)][at(f)];
      // The solid's velocity on the face: mass-weighted with the drag
      // solved here (its bulk density is known), else the mean.
      const auto solid_face_value = [&](const CellField& u) {
        if (!(interior && drag)) return face_value(u);
        const double m_l = solid_bulk_density_[at(lower)];
        const double m_r = solid_bulk_density_[at(upper)];
        return m_l + m_r > 0.0 ? (m_l * u[at(lower)] + m_r * u[at(upper)]) / (m_l + m_r) : 0.0;
      };
      u_s = solid_face_value(state_.solid_velocity[at(d)]);
      const bool open = type == SideType::fixed_pressure;
      // The solid fraction of the upwind cell; through a side of the domain
      // only outflow.
      // A held solid (the solid solver marks a rigid body with an immense
      // bulk density) moves only with the porosity the solid solver sends: no
      // solid crosses a face of its cells within a window. The water in its
      // cells is tied to it by an impermeable drag; pores the face flux
      // opened or closed would strain that water to cavitation within a few
      // windows (a rigid bed under sliding sand: 1.5 MPa and 0 Pa side by side).
      const auto held = [&](int c) {
        return drag && solid_bulk_density_[at(c)] > held_solid_bulk_density;
      };
      if (type == SideType::wall) {
        phi_s = 0.0;
      } else if (interior) {
        phi_s = held(lower) || held(upper) ? 0.0
                                           : 1.0 - state_.porosity[at(u_s >= 0.0 ? lower : upper)];
      } else {
        const bool outflow = upper_side ? u_s > 0.0 : u_s < 0.0;
        phi_s = outflow && !held(cell) ? 1.0 - state_.porosity[at(cell)] : 0.0;
      }
      if (drag && open) {
        weight[solid] = face_value(solid_bulk_density_);
        const double porosity = face_value(state_.porosity);
        const double drag_coefficient =
            interior ? face_drag(lower, upper, porosity, d, f, face_velocity_)
                     : solid_drag_[at(cell)];
        for (std::size_t i = 0; i < total * total; ++i) coefficient[i] = 0.0;
        if (fluid_exchange) {
          for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) {
              coefficient[i * total + j] =
                  exchange_.momentum[i * n + j] * fraction[i] * fraction[j];
            }
          }
        }
        for (std::size_t m = 0; m < n; ++m)
          coefficient[m * total + solid] =
              drag_coefficient * drag_share_[m] * fraction[m] / porosity;
        for (std::size_t m = 0; m < n; ++m) value[m] = face_velocity_[m][at(d)][at(f)];
        // The drag acts on the fluids' flux relative to the solid,
        // q = F - U_s with F the mixture's volume flux through the face: the
        // solid's velocity as the fluids' partner is (1 - phi_s,FC) U_s / n_up.
        // Inside a medium that is U_s; where the solid recedes from the face
        // (a settling surface: phi_s,FC = 0) it is U_s / n_up, the relative
        // velocity of the pore water that the surface's half cell resists.
        const double n_up =
            interior ? fluid_upwind_porosity(lower, upper, d, f, face_velocity_) : porosity;
        value[solid] = (1.0 - phi_s) * solid_face_value(solid_exchange_velocity_[at(d)]) / n_up;
        cosim::exchange::solve_implicit_exchange(w, x, 1, k, dt, dx);
        for (std::size_t m = 0; m < n; ++m) face_velocity_[m][at(d)][at(f)] += increment[m];
        // The pressure correction holds the solid (infinite weight): it
        // answers the pressure in the solid solver, with its stresses. The
        // new coefficients are solved for directly: y + dy cancels to zero
        // or below for a trace of air tied to an impermeable solid
        // (w << dt K), and 1 / rho_FC with it.
        weight[solid] = std::numeric_limits<double>::infinity();
        for (std::size_t m = 0; m < n; ++m) value[m] = face_correction_[m][at(d)][at(f)];
        value[solid] = 0.0;
        cosim::exchange::solve_implicit_exchange_values(w, x, 1, k, dt, dx);
        for (std::size_t m = 0; m < n; ++m) face_correction_[m][at(d)][at(f)] = increment[m];
      } else if (fluid_exchange && open) {
        const std::span<double> wn(weight.data(), n);
        const std::span<double> xn(value.data(), n);
        const std::span<double> dxn(increment.data(), n);
        const std::span<double> kn(coefficient.data(), n * n);
        for (std::size_t i = 0; i < n; ++i) {
          for (std::size_t j = 0; j < n; ++j) {
            coefficient[i * n + j] = exchange_.momentum[i * n + j] * fraction[i] * fraction[j];
          }
        }
        for (std::size_t m = 0; m < n; ++m) value[m] = face_velocity_[m][at(d)][at(f)];
        cosim::exchange::solve_implicit_exchange(wn, xn, 1, kn, dt, dxn);
        for (std::size_t m = 0; m < n; ++m) face_velocity_[m][at(d)][at(f)] += increment[m];
        for (std::size_t m = 0; m < n; ++m) value[m] = face_correction_[m][at(d)][at(f)];
        cosim::exchange::solve_implicit_exchange(wn, xn, 1, kn, dt, dxn);
        for (std::size_t m = 0; m < n; ++m) face_correction_[m][at(d)][at(f)] += increment[m];
      }
    }
  }
}

// exchange_face_momentum for two fluids without the drag (a water-air
// case, or the drag left to the coupler), face by face without index
// divisions: the solid's face velocity and upwind fraction, then eq. 131's
// closed form, one resistance for the velocities and the correction (as
// solve_implicit_exchange forms it).
template <int Dim>
void IceSolver<Dim>::exchange_two_fluid_faces(double dt) {
  const double k = exchange_.momentum[1];
  const double* rhobar_0 = state_.materials[0].bulk_density.data();
  const double* rhobar_1 = state_.materials[1].bulk_density.data();
  const double* phi_0 = state_.materials[0].volume_fraction.data();
  const double* phi_1 = state_.materials[1].volume_fraction.data();
  const double* porosity = state_.porosity.data();
  for (int d = 0; d < Dim; ++d) {
    const double* solid_velocity = state_.solid_velocity[at(d)].data();
    double* u_s = solid_face_velocity_[at(d)].data();
    double* phi_s = solid_face_fraction_[at(d)].data();
    double* u_0 = face_velocity_[0][at(d)].data();
    double* u_1 = face_velocity_[1][at(d)].data();
    double* y_0 = face_correction_[0][at(d)].data();
    double* y_1 = face_correction_[1][at(d)].data();
    const auto exchange = [&](int f, double w_0, double w_1, double fraction_0, double fraction_1) {
      const double dt_c = dt * (k * fraction_0 * fraction_1);
      if (!(w_0 > 0.0 && w_1 > 0.0 && dt_c > 0.0)) return;
      const double resistance = 1.0 / dt_c + 1.0 / w_0 + 1.0 / w_1;
      const double impulse = (u_1[f] - u_0[f]) / resistance;
      u_0[f] += impulse / w_0;
      u_1[f] += -impulse / w_1;
      const double correction = (y_1[f] - y_0[f]) / resistance;
      y_0[f] += correction / w_0;
      y_1[f] += -correction / w_1;
    };
    const int stride = grid_.stride(d);
    for_each_face_run(
        grid_, d,
        [&](int first, int end, int upper_offset) {
          for (int f = first; f < end; ++f) {
            const int upper = f - upper_offset;
            const int lower = upper - stride;
            u_s[f] = 0.5 * (solid_velocity[lower] + solid_velocity[upper]);
            phi_s[f] = 1.0 - porosity[u_s[f] >= 0.0 ? lower : upper];
          }
          interior_two_fluid_exchange(first, end, upper_offset, stride, dt, k, rhobar_0, rhobar_1,
                                      phi_0, phi_1, u_0, u_1, y_0, y_1);
        },
        [&](int f, int cell, bool upper_side) {
          const SideType type = sides_[at(2 * d + (upper_side ? 1 : 0))].type;
          u_s[f] = solid_velocity[cell];
          const bool outflow = upper_side ? u_s[f] > 0.0 : u_s[f] < 0.0;
          phi_s[f] = type != SideType::wall && outflow ? 1.0 - porosity[cell] : 0.0;
          if (type == SideType::fixed_pressure)
            exchange(f, rhobar_0[cell], rhobar_1[cell], phi_0[cell], phi_1[cell]);
        });
  }
}

template void IceSolver<1>::exchange_face_momentum(double);
template void IceSolver<1>::exchange_two_fluid_faces(double);
template void IceSolver<2>::exchange_face_momentum(double);
template void IceSolver<2>::exchange_two_fluid_faces(double);
template void IceSolver<3>::exchange_face_momentum(double);
template void IceSolver<3>::exchange_two_fluid_faces(double);

}  // namespace ice

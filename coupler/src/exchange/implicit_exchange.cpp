#include "cosim/exchange/implicit_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "cosim/error.hpp"

namespace cosim::exchange {

namespace {

// A nonsingular, weakly diagonally dominant M-matrix A = D - C given by its
// off-diagonal magnitudes C_ij >= 0 and its row excess s_i = A_ii - sum_j C_ij
// >= 0. Gaussian elimination that carries the excess along (Grassmann, Taksar
// and Heyman) forms every pivot and every update as a sum of non-negative
// terms, so the factors and A^-1 b for b >= 0 are accurate entry by entry
// whatever the spread of the coefficients (K from 1e-2 to 1e15 and beyond),
// where a standard LDLT loses the weak couplings to cancellation.
struct MMatrix {
  std::size_t size = 0;
  std::array<std::array<double, kMaxMaterials>, kMaxMaterials> off_diagonal{};
  std::array<double, kMaxMaterials> excess{};
  std::array<double, kMaxMaterials> pivot{};
  std::array<std::array<double, kMaxMaterials>, kMaxMaterials> multiplier{};

  void factor() {
    for (std::size_t k = 0; k < size; ++k) {
      pivot[k] = excess[k];
      for (std::size_t j = k + 1; j < size; ++j) pivot[k] += off_diagonal[k][j];
      for (std::size_t i = k + 1; i < size; ++i) {
        const double l = off_diagonal[i][k] / pivot[k];
        multiplier[i][k] = l;
        for (std::size_t j = k + 1; j < size; ++j) {
          if (j != i) off_diagonal[i][j] += l * off_diagonal[k][j];
        }
        excess[i] += l * excess[k];
      }
    }
  }

  // b <- A^-1 b
  void solve(std::array<double, kMaxMaterials>& b) const {
    for (std::size_t k = 0; k < size; ++k) {
      for (std::size_t i = k + 1; i < size; ++i) b[i] += multiplier[i][k] * b[k];
    }
    for (std::size_t k = size; k-- > 0;) {
      double sum = b[k];
      for (std::size_t j = k + 1; j < size; ++j) sum += off_diagonal[k][j] * b[j];
      b[k] = sum / pivot[k];
    }
  }
};

bool is_present(double weight) {
  return weight > 0;
}
bool is_held(double weight) {
  return std::isinf(weight) && weight > 0;
}

[[noreturn]] void throw_bad_sizes(std::size_t materials, std::size_t values, int components,
                                  std::size_t coefficients, std::size_t increments) {
  if (materials > kMaxMaterials || components < 1 || components > kMaxComponents) {
    throw std::invalid_argument(
        fmt::format("implicit exchange: {} materials x {} components (at most {} x {})", materials,
                    components, kMaxMaterials, kMaxComponents));
  }
  const std::size_t expected = materials * static_cast<std::size_t>(components);
  throw std::invalid_argument(fmt::format(
      "implicit exchange: {} materials x {} components need {} values/increments "
      "and {} coefficients, got {}/{} and {}",
      materials, components, expected, materials * materials, values, increments, coefficients));
}

// The messages are built out of line: this runs per face and per cell.
inline void check_sizes(std::size_t materials, std::size_t values, int components,
                        std::size_t coefficients, std::size_t increments) {
  const bool fits = materials <= kMaxMaterials && components >= 1 && components <= kMaxComponents;
  const std::size_t expected = materials * static_cast<std::size_t>(components);
  if (!fits || values != expected || increments != expected ||
      coefficients != materials * materials) {
    throw_bad_sizes(materials, values, components, coefficients, increments);
  }
}

[[noreturn]] void throw_bad_coefficient(std::size_t i, std::size_t j, double c) {
  throw NumericalError(fmt::format(
      "exchange coefficient between materials {} and {} must be finite and >= 0, got {}", i, j, c));
}

[[noreturn]] void throw_bad_time_step(double dt) {
  throw std::invalid_argument(fmt::format("implicit exchange: time step {} must be >= 0", dt));
}

inline double closed_form_impulse(double weight_1, double weight_2, double value_1, double value_2,
                                  double dt_coefficient) {
  if (!is_present(weight_1) || !is_present(weight_2) || !(dt_coefficient > 0)) return 0.0;
  const double resistance = 1.0 / dt_coefficient + 1.0 / weight_1 + 1.0 / weight_2;
  if (resistance == 0) return 0.0;  // two held materials tied rigidly: nothing moves
  return (value_2 - value_1) / resistance;
}

}  // namespace

double two_material_impulse(double weight_1, double weight_2, double value_1, double value_2,
                            double dt_coefficient) {
  return closed_form_impulse(weight_1, weight_2, value_1, value_2, dt_coefficient);
}

namespace {

// The present materials, split into the unknowns (those that can move) and
// the held ones that act as sources, each in index order.
struct ExchangePartners {
  std::array<std::size_t, kMaxMaterials> unknown{};
  std::array<std::size_t, kMaxMaterials> held{};
  std::size_t unknowns = 0;
  std::size_t held_count = 0;

  std::size_t present() const { return unknowns + held_count; }
};

ExchangePartners partition(std::span<const double> weight) {
  ExchangePartners p;
  for (std::size_t i = 0; i < weight.size(); ++i) {
    if (!is_present(weight[i])) continue;
    if (is_held(weight[i])) {
      p.held[p.held_count++] = i;
    } else {
      p.unknown[p.unknowns++] = i;
    }
  }
  return p;
}

// dt C_ij of a pair (the upper triangle of the n x n coefficients), checked.
struct DtCoupling {
  std::span<const double> coefficient;
  std::size_t n;
  double dt;

  double operator()(std::size_t i, std::size_t j) const {
    const double c = coefficient[std::min(i, j) * n + std::max(i, j)];
    if (!std::isfinite(c) || c < 0) throw_bad_coefficient(std::min(i, j), std::max(i, j), c);
    return dt * c;
  }
};

// (W + dt L) restricted to the unknowns, stored as an M-matrix (off-diagonal
// magnitudes dt C_ij and row excess w_i + sum_held dt C_ih) and factored.
MMatrix factored_exchange_system(const ExchangePartners& p, std::span<const double> weight,
                                 const DtCoupling& dt_coupling) {
  MMatrix system;
  system.size = p.unknowns;
  for (std::size_t a = 0; a < p.unknowns; ++a) {
    system.excess[a] = weight[p.unknown[a]];
    for (std::size_t h = 0; h < p.held_count; ++h) {
      system.excess[a] += dt_coupling(p.unknown[a], p.held[h]);
    }
    for (std::size_t b = 0; b < p.unknowns; ++b) {
      system.off_diagonal[a][b] = a == b ? 0.0 : dt_coupling(p.unknown[a], p.unknown[b]);
    }
  }
  system.factor();
  return system;
}

// Any number of materials, absent and held ones included.
[[gnu::noinline]] void solve_general(std::span<const double> weight, std::span<const double> value,
                                     std::size_t dim, std::span<const double> coefficient,
                                     double dt, std::span<double> increment) {
  const std::size_t n = weight.size();
  std::fill(increment.begin(), increment.end(), 0.0);
  const ExchangePartners partners = partition(weight);
  const DtCoupling dt_coupling{coefficient, n, dt};
  if (partners.present() < 2) return;

  if (partners.present() == 2) {
    // The pair in index order.
    const std::size_t first = partners.unknowns > 0 ? partners.unknown[0] : partners.held[0];
    const std::size_t second = partners.unknowns == 2     ? partners.unknown[1]
                               : partners.held_count == 2 ? partners.held[1]
                                                          : partners.held[0];
    const std::size_t i = std::min(first, second);
    const std::size_t j = std::max(first, second);
    const double dt_c = dt_coupling(i, j);
    for (std::size_t c = 0; c < dim; ++c) {
      const double impulse =
          closed_form_impulse(weight[i], weight[j], value[i * dim + c], value[j * dim + c], dt_c);
      if (!is_held(weight[i])) increment[i * dim + c] = impulse / weight[i];
      if (!is_held(weight[j])) increment[j * dim + c] = -impulse / weight[j];
    }
    return;
  }

  const std::size_t m = partners.unknowns;
  const std::size_t held_count = partners.held_count;
  const auto& unknown = partners.unknown;
  const auto& held = partners.held;
  if (m == 0) return;
  const MMatrix system = factored_exchange_system(partners, weight, dt_coupling);

  // Effective conductances G = W (W + dt L)^-1 W between unknowns, and
  // G_ih = w_i [(W + dt L)^-1 dt C_h]_i towards held materials. The increments
  // are sums of pairwise impulses G_ij (x*_j - x*_i), antisymmetric between
  // unknowns, so sum_i w_i dx_i = 0 up to the rounding of the sums.
  std::array<std::array<double, kMaxMaterials>, kMaxMaterials> conductance{};
  std::array<double, kMaxMaterials> column{};
  for (std::size_t b = 0; b < m; ++b) {
    column.fill(0.0);
    column[b] = weight[unknown[b]];
    system.solve(column);
    for (std::size_t a = 0; a < m; ++a) conductance[a][b] = weight[unknown[a]] * column[a];
  }
  for (std::size_t a = 0; a < m; ++a) {
    const std::size_t i = unknown[a];
    for (std::size_t c = 0; c < dim; ++c) {
      for (std::size_t b = a + 1; b < m; ++b) {
        const std::size_t j = unknown[b];
        const double g = 0.5 * (conductance[a][b] + conductance[b][a]);
        const double j_ab = g * (value[j * dim + c] - value[i * dim + c]);
        increment[i * dim + c] += j_ab;
        increment[j * dim + c] -= j_ab;
      }
    }
  }
  for (std::size_t h = 0; h < held_count; ++h) {
    for (std::size_t a = 0; a < m; ++a) column[a] = dt_coupling(unknown[a], held[h]);
    system.solve(column);
    for (std::size_t a = 0; a < m; ++a) {
      const std::size_t i = unknown[a];
      for (std::size_t c = 0; c < dim; ++c) {
        increment[i * dim + c] +=
            weight[i] * column[a] * (value[held[h] * dim + c] - value[i * dim + c]);
      }
    }
  }
  for (std::size_t a = 0; a < m; ++a) {
    const std::size_t i = unknown[a];
    for (std::size_t c = 0; c < dim; ++c) increment[i * dim + c] /= weight[i];
  }
}

}  // namespace

void solve_implicit_exchange(std::span<const double> weight, std::span<const double> value,
                             int components, std::span<const double> coefficient, double dt,
                             std::span<double> increment) {
  const std::size_t n = weight.size();
  check_sizes(n, value.size(), components, coefficient.size(), increment.size());
  if (!std::isfinite(dt) || dt < 0) throw_bad_time_step(dt);
  const auto dim = static_cast<std::size_t>(components);
  if (n == 2 && is_present(weight[0]) && is_present(weight[1]) && !is_held(weight[0]) &&
      !is_held(weight[1])) {
    // Two ordinary materials (the ICE step's every face and cell): the
    // closed form of two_material_impulse, its resistance formed once for
    // all components, without the general path's bookkeeping.
    const double c = coefficient[1];
    if (!std::isfinite(c) || c < 0) throw_bad_coefficient(0, 1, c);
    // The divisions by the two weights are done in pairs (one packed
    // division each: the same quotients, half the divider's time).
    using Pair = double __attribute__((vector_size(16)));
    const Pair w = {weight[0], weight[1]};
    const Pair inverse = 1.0 / w;
    const double dt_c = dt * c;
    const double resistance = 1.0 / dt_c + inverse[0] + inverse[1];
    const bool moves = dt_c > 0 && resistance != 0;
    for (std::size_t k = 0; k < dim; ++k) {
      const double impulse = moves ? (value[dim + k] - value[k]) / resistance : 0.0;
      const Pair share = Pair{impulse, -impulse} / w;
      increment[k] = share[0];
      increment[dim + k] = share[1];
    }
    return;
  }
  solve_general(weight, value, dim, coefficient, dt, increment);
}

void solve_implicit_exchange_values(std::span<const double> weight, std::span<const double> value,
                                    int components, std::span<const double> coefficient, double dt,
                                    std::span<double> new_value) {
  const std::size_t n = weight.size();
  check_sizes(n, value.size(), components, coefficient.size(), new_value.size());
  if (!std::isfinite(dt) || dt < 0) throw_bad_time_step(dt);
  const auto dim = static_cast<std::size_t>(components);
  std::copy(value.begin(), value.end(), new_value.begin());
  const ExchangePartners partners = partition(weight);
  const std::size_t m = partners.unknowns;
  const std::size_t held_count = partners.held_count;
  const auto& unknown = partners.unknown;
  const auto& held = partners.held;
  if (m == 0 || partners.present() < 2) return;
  const DtCoupling dt_coupling{coefficient, n, dt};
  const MMatrix system = factored_exchange_system(partners, weight, dt_coupling);
  std::array<double, kMaxMaterials> column{};
  for (std::size_t c = 0; c < dim; ++c) {
    for (std::size_t a = 0; a < m; ++a) {
      const std::size_t i = unknown[a];
      double rhs = weight[i] * value[i * dim + c];
      for (std::size_t h = 0; h < held_count; ++h) {
        rhs += dt_coupling(i, held[h]) * value[held[h] * dim + c];
      }
      column[a] = rhs;
    }
    system.solve(column);
    for (std::size_t a = 0; a < m; ++a) new_value[unknown[a] * dim + c] = column[a];
  }
}

void exchange_momentum(std::span<const double> bulk_density, std::span<const double> velocity,
                       int dim, std::span<const double> drag, double dt,
                       std::span<double> velocity_increment) {
  solve_implicit_exchange(bulk_density, velocity, dim, drag, dt, velocity_increment);
}

void exchange_energy(std::span<const double> bulk_density, std::span<const double> specific_heat,
                     std::span<const double> temperature, std::span<const double> heat_exchange,
                     double dt, std::span<double> temperature_increment) {
  const std::size_t n = bulk_density.size();
  if (specific_heat.size() != n || n > kMaxMaterials) {
    throw std::invalid_argument(
        fmt::format("energy exchange: {} bulk densities, {} specific heats (at most {})", n,
                    specific_heat.size(), kMaxMaterials));
  }
  std::array<double, kMaxMaterials> heat_capacity{};
  for (std::size_t i = 0; i < n; ++i) heat_capacity[i] = bulk_density[i] * specific_heat[i];
  solve_implicit_exchange(std::span<const double>(heat_capacity.data(), n), temperature, 1,
                          heat_exchange, dt, temperature_increment);
}

}  // namespace cosim::exchange

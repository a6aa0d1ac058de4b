#include "cosim/exchange/implicit_exchange.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::exchange {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Material {
  std::vector<double> weight;       // N
  std::vector<double> value;        // N x dim
  std::vector<double> coefficient;  // N x N symmetric
};

double log_uniform(std::mt19937_64& rng, double low, double high) {
  std::uniform_real_distribution<double> exponent(std::log10(low), std::log10(high));
  return std::pow(10.0, exponent(rng));
}

Material random_materials(std::mt19937_64& rng, std::size_t n, int dim, double max_coefficient) {
  std::uniform_real_distribution<double> velocity(-10.0, 10.0);
  Material m;
  m.weight.resize(n);
  m.value.resize(n * static_cast<std::size_t>(dim));
  m.coefficient.assign(n * n, 0.0);
  for (auto& w : m.weight) w = log_uniform(rng, 1.0, 3000.0);
  for (auto& v : m.value) v = velocity(rng);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      m.coefficient[i * n + j] = m.coefficient[j * n + i] = log_uniform(rng, 1e-2, max_coefficient);
    }
  }
  return m;
}

// |sum_i w_i dx_i| / sum_i w_i |x*_i|, worst component.
double momentum_error(const Material& m, int dim, const std::vector<double>& increment) {
  const auto d = static_cast<std::size_t>(dim);
  double worst = 0;
  for (std::size_t c = 0; c < d; ++c) {
    double imbalance = 0;
    double scale = 0;
    for (std::size_t i = 0; i < m.weight.size(); ++i) {
      imbalance += m.weight[i] * increment[i * d + c];
      scale += m.weight[i] * std::abs(m.value[i * d + c]);
    }
    worst = std::max(worst, std::abs(imbalance) / scale);
  }
  return worst;
}

// Residual of w_i dx_i = dt sum_j C_ij (x_j + dx_j - x_i - dx_i), relative to
// the sum of the magnitudes of its terms.
double equation_residual(const Material& m, int dim, double dt,
                         const std::vector<double>& increment) {
  const std::size_t n = m.weight.size();
  const auto d = static_cast<std::size_t>(dim);
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < d; ++c) {
      const double xi = m.value[i * d + c] + increment[i * d + c];
      double residual = m.weight[i] * increment[i * d + c];
      double magnitude = std::abs(residual);
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const double dtc = dt * m.coefficient[i * n + j];
        const double xj = m.value[j * d + c] + increment[j * d + c];
        residual -= dtc * (xj - xi);
        magnitude += dtc * (std::abs(xj) + std::abs(xi));
      }
      worst = std::max(worst, std::abs(residual) / magnitude);
    }
  }
  return worst;
}

TEST(ImplicitExchange, ConservesMomentumToRoundOffForRandomInputs) {
  std::mt19937_64 rng(20240607);
  const double dt = 1e-3;
  for (const std::size_t n : {2u, 3u, 4u}) {
    for (int dim = 1; dim <= 3; ++dim) {
      double worst_momentum = 0;
      double worst_residual = 0;
      for (int sample = 0; sample < 200; ++sample) {
        const Material m = random_materials(rng, n, dim, 1e15);
        std::vector<double> increment(m.value.size());
        exchange_momentum(m.weight, m.value, dim, m.coefficient, dt, increment);
        for (const double v : increment) ASSERT_TRUE(std::isfinite(v));
        worst_momentum = std::max(worst_momentum, momentum_error(m, dim, increment));
        worst_residual = std::max(worst_residual, equation_residual(m, dim, dt, increment));
      }
      std::printf("N = %zu, dim = %d: max relative momentum error %.3g, max residual %.3g\n", n,
                  dim, worst_momentum, worst_residual);
      EXPECT_LT(worst_momentum, 1e-14);
      EXPECT_LT(worst_residual, 1e-12);
    }
  }
}

TEST(ImplicitExchange, TwoMaterialsRelativeVelocityDecaysAsTranEq131) {
  const std::vector<double> weight{1000.0, 1600.0};
  const std::vector<double> velocity{2.0, -1.0};
  const double k = 5.0e5;
  const std::vector<double> drag{0.0, k, k, 0.0};
  const double dt = 1e-3;
  std::vector<double> increment(2);
  exchange_momentum(weight, velocity, 1, drag, dt, increment);
  const double relative = velocity[0] + increment[0] - velocity[1] - increment[1];
  const double expected = 3.0 / (1.0 + dt * k * (1.0 / 1000.0 + 1.0 / 1600.0));
  std::printf("relative velocity %.17g, closed form %.17g\n", relative, expected);
  EXPECT_NEAR(relative, expected, 1e-14 * 3.0);
  // The 2x2 system of eq. 131 with beta_12 = dt K / rho_1, beta_21 = dt K / rho_2.
  const double beta12 = dt * k / weight[0];
  const double beta21 = dt * k / weight[1];
  EXPECT_NEAR((1 + beta12) * increment[0] - beta12 * increment[1], beta12 * (-1.0 - 2.0), 1e-13);
  EXPECT_NEAR(-beta21 * increment[0] + (1 + beta21) * increment[1], beta21 * (2.0 + 1.0), 1e-13);
}

TEST(ImplicitExchange, GeneralSolveAgreesWithTheClosedForm) {
  // Material 2 couples to nothing, so the three-material path must reproduce the
  // two-material closed form for materials 0 and 1.
  std::mt19937_64 rng(7);
  double worst = 0;
  for (int sample = 0; sample < 100; ++sample) {
    Material m = random_materials(rng, 3, 3, 1e12);
    m.coefficient[0 * 3 + 2] = m.coefficient[2 * 3 + 0] = 0.0;
    m.coefficient[1 * 3 + 2] = m.coefficient[2 * 3 + 1] = 0.0;
    std::vector<double> general(9);
    exchange_momentum(m.weight, m.value, 3, m.coefficient, 1e-3, general);
    const std::vector<double> pair_weight{m.weight[0], m.weight[1]};
    const std::vector<double> pair_value(m.value.begin(), m.value.begin() + 6);
    const std::vector<double> pair_drag{0.0, m.coefficient[1], m.coefficient[1], 0.0};
    std::vector<double> closed(6);
    exchange_momentum(pair_weight, pair_value, 3, pair_drag, 1e-3, closed);
    for (std::size_t k = 0; k < 6; ++k) {
      worst = std::max(worst, std::abs(general[k] - closed[k]) / (1.0 + std::abs(closed[k])));
    }
    for (std::size_t k = 6; k < 9; ++k) EXPECT_EQ(general[k], 0.0);
  }
  std::printf("general solve vs closed form: max difference %.3g\n", worst);
  EXPECT_LT(worst, 1e-10);
}

TEST(ImplicitExchange, StiffCouplingGivesEqualFiniteVelocities) {
  const double dt = 1e-3;
  for (const std::size_t n : {2u, 3u, 4u}) {
    std::mt19937_64 rng(n);
    Material m = random_materials(rng, n, 3, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) m.coefficient[i * n + j] = i == j ? 0.0 : 1e15;
    }
    std::vector<double> increment(m.value.size());
    exchange_momentum(m.weight, m.value, 3, m.coefficient, dt, increment);
    double spread = 0;
    double mixture_error = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      double momentum = 0;
      double mass = 0;
      for (std::size_t i = 0; i < n; ++i) {
        momentum += m.weight[i] * m.value[i * 3 + c];
        mass += m.weight[i];
      }
      const double mixture = momentum / mass;
      for (std::size_t i = 0; i < n; ++i) {
        const double final_velocity = m.value[i * 3 + c] + increment[i * 3 + c];
        ASSERT_TRUE(std::isfinite(final_velocity));
        spread = std::max(spread, std::abs(final_velocity - m.value[c] - increment[c]));
        mixture_error = std::max(mixture_error, std::abs(final_velocity - mixture));
      }
    }
    // beta = dt K / rho ~ 1e9: the phases differ by ~ |w*| / beta plus round-off.
    std::printf("N = %zu, K = 1e15: velocity spread %.3g m/s, distance to mixture velocity %.3g\n",
                n, spread, mixture_error);
    EXPECT_LT(spread, 1e-7);
    EXPECT_LT(mixture_error, 1e-7);
  }
}

TEST(ImplicitExchange, AbsentMaterialsTakePartInNothing) {
  const std::vector<double> weight{1000.0, 0.0, 2000.0, 0.0};
  const std::vector<double> velocity{1.0, 50.0, -2.0, 7.0};
  std::vector<double> drag(16, 1e6);
  std::vector<double> increment(4, 99.0);
  exchange_momentum(weight, velocity, 1, drag, 1e-3, increment);
  EXPECT_EQ(increment[1], 0.0);
  EXPECT_EQ(increment[3], 0.0);
  const double relative = 3.0 / (1.0 + 1e3 * (1.0 / 1000.0 + 1.0 / 2000.0));
  EXPECT_NEAR(velocity[0] + increment[0] - velocity[2] - increment[2], relative, 1e-14);
  EXPECT_NEAR(1000.0 * increment[0] + 2000.0 * increment[2], 0.0, 1e-12);

  const std::vector<double> alone{0.0, 0.0, 1000.0};
  std::vector<double> none(3, 5.0);
  exchange_momentum(alone, {velocity.data(), 3}, 1, {drag.data(), 9}, 1e-3, none);
  EXPECT_EQ(none, std::vector<double>(3, 0.0));
}

TEST(ImplicitExchange, HeldMaterialKeepsItsVelocity) {
  // A held (infinite-inertia) solid at rest: the fluid relaxes towards it
  // as U / (1 + dt K / rho_f), for two and for three materials.
  const double k = 2e6;
  const double dt = 1e-3;
  std::vector<double> increment(2);
  exchange_momentum(std::vector<double>{1000.0, kInf}, std::vector<double>{1.5, 0.0}, 1,
                    std::vector<double>{0, k, k, 0}, dt, increment);
  EXPECT_EQ(increment[1], 0.0);
  EXPECT_NEAR(1.5 + increment[0], 1.5 / (1.0 + dt * k / 1000.0), 1e-15);

  std::vector<double> three(3);
  exchange_momentum(std::vector<double>{1000.0, kInf, 1.2}, std::vector<double>{1.5, 0.0, 1.5}, 1,
                    std::vector<double>{0, k, 1e5, k, 0, 0, 1e5, 0, 0}, dt, three);
  // Unknowns dU_0, dU_2 with dU_1 = 0, solved by Cramer's rule.
  const double a00 = 1000.0 + dt * (k + 1e5);
  const double a02 = -dt * 1e5;
  const double a22 = 1.2 + dt * 1e5;
  const double b0 = dt * k * (0.0 - 1.5);
  const double det = a00 * a22 - a02 * a02;
  EXPECT_EQ(three[1], 0.0);
  EXPECT_NEAR(three[0], b0 * a22 / det, 1e-14);
  EXPECT_NEAR(three[2], -a02 * b0 / det, 1e-14);
}

TEST(ImplicitExchangeValues, AgreeWithTheIncrementsForRandomInputs) {
  // Without held materials both forms solve the same system: new values
  // x* + dx within 1e-12 of the largest |x*| of the sample.
  std::mt19937_64 rng(7);
  const double dt = 1e-3;
  double worst = 0;
  for (const std::size_t n : {2u, 3u, 4u}) {
    for (int dim = 1; dim <= 3; ++dim) {
      for (int sample = 0; sample < 100; ++sample) {
        const Material m = random_materials(rng, n, dim, 1e15);
        std::vector<double> increment(m.value.size()), values(m.value.size());
        solve_implicit_exchange(m.weight, m.value, dim, m.coefficient, dt, increment);
        solve_implicit_exchange_values(m.weight, m.value, dim, m.coefficient, dt, values);
        double scale = 0;
        for (const double v : m.value) scale = std::max(scale, std::abs(v));
        for (std::size_t i = 0; i < values.size(); ++i)
          worst = std::max(worst, std::abs(values[i] - (m.value[i] + increment[i])) / scale);
      }
    }
  }
  std::printf("largest difference of the new values from x* + dx: %.3g of max |x*|\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(ImplicitExchangeValues, TraceTiedToAHeldMaterialKeepsItsSmallPositiveValue) {
  // The face coefficients of ICE's pressure correction on a face between an
  // impermeable held solid and a soil cell (a coupled run that failed with
  // "face density ... inf"): water (w = 175 kg/m3, y = 1.0e-3), a trace of
  // air (w = 8e-7, y = 78), the held solid at 0, dt = 1e-3 s, K_water,solid
  // = 1e16, K_air,solid = 3.6e12, K_water,air = 1.1e10. The new values are
  // positive and equal the exact solution (Cramer's rule in long double) to
  // 1e-12 of their own size; x* + dx from the increments cancels to ~0 for
  // the air.
  const double dt = 1e-3;
  const std::vector<double> weight{175.0, 8e-7, kInf};
  const std::vector<double> value{1.0e-3, 78.0, 0.0};
  const double k_ws = 1e16, k_as = 3.6e12, k_wa = 1.1e10;
  const std::vector<double> coefficient{0, k_wa, k_ws, k_wa, 0, k_as, k_ws, k_as, 0};
  std::vector<double> values(3), increment(3);
  solve_implicit_exchange_values(weight, value, 1, coefficient, dt, values);
  solve_implicit_exchange(weight, value, 1, coefficient, dt, increment);
  using Long = long double;
  const Long a00 = Long(175.0) + Long(dt) * (Long(k_wa) + Long(k_ws));
  const Long a11 = Long(8e-7) + Long(dt) * (Long(k_wa) + Long(k_as));
  const Long a01 = -Long(dt) * Long(k_wa);
  const Long b0 = Long(175.0) * Long(1.0e-3), b1 = Long(8e-7) * Long(78.0);
  const Long det = a00 * a11 - a01 * a01;
  const double exact[] = {static_cast<double>((b0 * a11 - a01 * b1) / det),
                          static_cast<double>((a00 * b1 - a01 * b0) / det)};
  for (int i = 0; i < 2; ++i) {
    std::printf("material %d: new value %.6g (exact %.6g), from the increment %.6g\n", i,
                values[static_cast<std::size_t>(i)], exact[i],
                value[static_cast<std::size_t>(i)] + increment[static_cast<std::size_t>(i)]);
    EXPECT_GT(values[static_cast<std::size_t>(i)], 0.0);
    EXPECT_NEAR(values[static_cast<std::size_t>(i)], exact[i], 1e-12 * exact[i]);
  }
  EXPECT_EQ(values[2], 0.0);
}

TEST(ImplicitExchange, RejectsInvalidCoefficientsAndSizes) {
  std::vector<double> increment(3);
  EXPECT_THROW(exchange_momentum(std::vector<double>{1, 1, 1}, std::vector<double>{0, 1, 2}, 1,
                                 std::vector<double>{0, -1, 0, -1, 0, 0, 0, 0, 0}, 1e-3, increment),
               NumericalError);
  EXPECT_THROW(exchange_momentum(std::vector<double>{1, 1, 1}, std::vector<double>{0, 1}, 1,
                                 std::vector<double>(9, 1.0), 1e-3, increment),
               std::invalid_argument);
}

TEST(EnergyExchange, ConservesEnergyAndRelaxesTemperatures) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> temperature(250.0, 400.0);
  double worst = 0;
  for (const std::size_t n : {2u, 3u, 4u}) {
    for (int sample = 0; sample < 100; ++sample) {
      std::vector<double> rho(n), cv(n), t(n), h(n * n, 0.0), dt_increment(n);
      for (std::size_t i = 0; i < n; ++i) {
        rho[i] = log_uniform(rng, 1.0, 3000.0);
        cv[i] = log_uniform(rng, 700.0, 4200.0);
        t[i] = temperature(rng);
        for (std::size_t j = i + 1; j < n; ++j)
          h[i * n + j] = h[j * n + i] = log_uniform(rng, 1, 1e12);
      }
      exchange_energy(rho, cv, t, h, 1e-2, dt_increment);
      double change = 0;
      double total = 0;
      for (std::size_t i = 0; i < n; ++i) {
        change += rho[i] * cv[i] * dt_increment[i];
        total += rho[i] * cv[i] * t[i];
        ASSERT_TRUE(std::isfinite(dt_increment[i]));
      }
      worst = std::max(worst, std::abs(change) / total);
    }
  }
  std::printf("energy exchange: max relative change of sum rho c_v T: %.3g\n", worst);
  EXPECT_LT(worst, 1e-15);

  // Two materials: the difference decays as (T1 - T2) / (1 + eta_12 + eta_21).
  std::vector<double> increment(2);
  const double h = 1e4;
  exchange_energy(std::vector<double>{1000.0, 1.2}, std::vector<double>{4186.0, 718.0},
                  std::vector<double>{300.0, 350.0}, std::vector<double>{0, h, h, 0}, 0.1,
                  increment);
  const double eta = 0.1 * h / (1000.0 * 4186.0) + 0.1 * h / (1.2 * 718.0);
  EXPECT_NEAR(300.0 + increment[0] - 350.0 - increment[1], -50.0 / (1.0 + eta), 1e-12);
}

}  // namespace
}  // namespace cosim::exchange

#include "exchange/two_phase_exchange.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "cosim/error.hpp"
#include "cosim/exchange/implicit_exchange.hpp"
#include "exchange/constant_drag.hpp"
#include "exchange/drag_law_registry.hpp"
#include "exchange/kozeny_carman.hpp"

namespace cosim::exchange {
namespace {

// Owns the arrays of an exchange over `cells` cells.
struct Cells {
  Cells(std::size_t cells, int components)
      : dim(components),
        volume(cells, 1.0),
        rho_f(cells, 1000.0 * 0.6),
        rho_s(cells, 2650.0 * 0.4),
        phi_s(cells, 0.4),
        u_f(cells * static_cast<std::size_t>(components), 0.0),
        u_s(cells * static_cast<std::size_t>(components), 0.0),
        du_f(u_f.size()),
        du_s(u_f.size()),
        impulse_f(u_f.size()),
        impulse_s(u_f.size()),
        drag(cells) {}

  void exchange(const DragLaw& law, double dt) {
    exchange_two_phase(law, dim, dt, volume, {rho_f, u_f}, {rho_s, u_s}, {phi_s, {}, {}},
                       {du_f, du_s, impulse_f, impulse_s, drag});
  }
  void apply() {
    for (std::size_t k = 0; k < u_f.size(); ++k) {
      u_f[k] += du_f[k];
      u_s[k] += du_s[k];
    }
  }

  int dim;
  std::vector<double> volume, rho_f, rho_s, phi_s, u_f, u_s, du_f, du_s, impulse_f, impulse_s, drag;
};

std::unique_ptr<DragLaw> kozeny_carman() {
  return make_drag_law(
      YAML::Load("{law: kozeny_carman, grain_size: 1.0e-4, fluid_viscosity: 1.0e-3}"), "drag");
}

TEST(TwoPhaseExchange, ConservesMomentumPerCellAndReturnsImpulses) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto law = kozeny_carman();
  for (int dim = 1; dim <= 3; ++dim) {
    Cells cells(500, dim);
    const auto d = static_cast<std::size_t>(dim);
    for (std::size_t c = 0; c < cells.volume.size(); ++c) {
      cells.volume[c] = 1e-3 + uniform(rng);
      cells.phi_s[c] = 0.05 + 0.6 * uniform(rng);
      cells.rho_f[c] = 1000.0 * (1.0 - cells.phi_s[c]);
      cells.rho_s[c] = 2650.0 * cells.phi_s[c];
    }
    for (auto& u : cells.u_f) u = 20.0 * uniform(rng) - 10.0;
    for (auto& u : cells.u_s) u = 20.0 * uniform(rng) - 10.0;
    cells.rho_s[7] = 0.0;  // a cell without soil
    cells.exchange(*law, 1e-3);
    double worst = 0;
    double worst_impulse = 0;
    for (std::size_t c = 0; c < cells.volume.size(); ++c) {
      for (std::size_t k = 0; k < d; ++k) {
        const std::size_t at = c * d + k;
        const double momentum = cells.rho_f[c] * cells.u_f[at] + cells.rho_s[c] * cells.u_s[at];
        const double scale =
            cells.rho_f[c] * std::abs(cells.u_f[at]) + cells.rho_s[c] * std::abs(cells.u_s[at]);
        const double change = cells.rho_f[c] * cells.du_f[at] + cells.rho_s[c] * cells.du_s[at];
        worst = std::max(worst, std::abs(change) / scale);
        EXPECT_EQ(cells.impulse_s[at], -cells.impulse_f[at]);
        worst_impulse = std::max(
            worst_impulse,
            std::abs(cells.impulse_f[at] - cells.rho_f[c] * cells.du_f[at] * cells.volume[c]) /
                (std::abs(momentum) + scale));
      }
    }
    std::printf("dim %d: max relative momentum change per cell %.3g, impulse vs rho dU V %.3g\n",
                dim, worst, worst_impulse);
    EXPECT_LT(worst, 1e-15);
    EXPECT_LT(worst_impulse, 1e-15);
    for (std::size_t k = 0; k < d; ++k) {
      EXPECT_EQ(cells.du_f[7 * d + k], 0.0);
      EXPECT_EQ(cells.du_s[7 * d + k], 0.0);
    }
    EXPECT_EQ(cells.drag[7], 0.0);
    EXPECT_DOUBLE_EQ(cells.drag[0], 180.0 * cells.phi_s[0] * cells.phi_s[0] * 1e-3 /
                                        (1e-8 * (1.0 - cells.phi_s[0])));
  }
}

TEST(TwoPhaseExchange, SteadyStateIsDarcyFlow) {
  // A body force density f drives the pore water; the skeleton is held by its
  // support, which carries the reaction -f (at steady state the mixture does
  // not accelerate). Repeated windows converge to w = f / K (Darcy).
  const auto law = kozeny_carman();
  const double f = 9810.0 * 0.01;  // N m^-3, a hydraulic gradient of 0.01
  Cells cells(3, 2);
  cells.phi_s = {0.2, 0.4, 0.6};
  for (std::size_t c = 0; c < 3; ++c) {
    cells.rho_f[c] = 1000.0 * (1.0 - cells.phi_s[c]);
    cells.rho_s[c] = 2650.0 * cells.phi_s[c];
  }
  const double dt = 1e-3;
  for (int window = 0; window < 2000; ++window) {
    for (std::size_t c = 0; c < 3; ++c) {
      cells.u_f[2 * c] += dt * f / cells.rho_f[c];
      cells.u_s[2 * c] -= dt * f / cells.rho_s[c];
    }
    cells.exchange(*law, dt);
    cells.apply();
  }
  for (std::size_t c = 0; c < 3; ++c) {
    const double darcy = f / cells.drag[c];
    const double w = cells.u_f[2 * c] - cells.u_s[2 * c];
    const double error = std::abs(w - darcy) / darcy;
    std::printf("phi_s %.1f: K %.4e, w %.12e m/s, Darcy f/K %.12e, rel. error %.3g\n",
                cells.phi_s[c], cells.drag[c], w, darcy, error);
    EXPECT_LT(error, 1e-10);
    EXPECT_EQ(cells.u_f[2 * c + 1], 0.0);
  }
}

TEST(TwoPhaseExchange, HeldSolidOfInfiniteInertiaGivesDarcyExactly) {
  // The same with the skeleton as a held material (infinite bulk density):
  // the fluid alone converges to U_f = f / K.
  const double k = 1.2e7;
  const double f = 98.1;
  const double rho_f = 600.0;
  const double dt = 1e-3;
  std::vector<double> velocity{0.0, 0.0};
  std::vector<double> increment(2);
  for (int window = 0; window < 500; ++window) {
    velocity[0] += dt * f / rho_f;
    exchange_momentum(std::vector<double>{rho_f, std::numeric_limits<double>::infinity()}, velocity,
                      1, std::vector<double>{0, k, k, 0}, dt, increment);
    velocity[0] += increment[0];
    ASSERT_EQ(increment[1], 0.0);
  }
  const double error = std::abs(velocity[0] - f / k) / (f / k);
  std::printf("held solid: U_f %.15e, f/K %.15e, rel. error %.3g\n", velocity[0], f / k, error);
  EXPECT_LT(error, 1e-12);
}

TEST(TwoPhaseExchange, SolidResetToRestAfterTheExchangeLeavesASplittingError) {
  // Holding the skeleton by resetting its velocity after the exchange throws
  // away the impulse it received; the fluid then settles at
  // U_f = f / K + f dt / rho_s, not at Darcy's f / K.
  const double k = 1.2e7;
  const double f = 98.1;
  const double dt = 1e-3;
  const ConstantDrag law(k);
  Cells cells(1, 1);
  for (int window = 0; window < 500; ++window) {
    cells.u_f[0] += dt * f / cells.rho_f[0];
    cells.exchange(law, dt);
    cells.apply();
    cells.u_s[0] = 0.0;
  }
  const double predicted = f / k + f * dt / cells.rho_s[0];
  std::printf("solid reset: U_f %.6e, f/K %.6e (error %.3g), f/K + f dt/rho_s %.6e\n", cells.u_f[0],
              f / k, std::abs(cells.u_f[0] - f / k) / (f / k), predicted);
  EXPECT_NEAR(cells.u_f[0], predicted, 1e-12 * predicted);
}

TEST(TwoPhaseExchange, ImpermeableStructureMovesWithTheFluid) {
  const ConstantDrag law(1e15);
  Cells cells(2, 3);
  cells.u_f = {1.0, -2.0, 3.0, 1e3, 0.0, -1e3};
  cells.u_s = {0.0, 0.0, 0.0, -1e3, 5.0, 1e3};
  cells.exchange(law, 1e-2);
  cells.apply();
  double worst = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    ASSERT_TRUE(std::isfinite(cells.u_f[k]));
    worst = std::max(worst, std::abs(cells.u_f[k] - cells.u_s[k]) / (1.0 + std::abs(cells.u_f[k])));
  }
  std::printf("K = 1e15: max relative velocity difference after exchange %.3g\n", worst);
  EXPECT_LT(worst, 1e-9);
}

TEST(TwoPhaseExchange, RejectsNonFiniteInputsAndMismatchedSizes) {
  const auto law = kozeny_carman();
  Cells cells(4, 2);
  cells.u_f[5] = std::numeric_limits<double>::quiet_NaN();
  try {
    cells.exchange(*law, 1e-3);
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& error) {
    std::printf("%s\n", error.what());
    EXPECT_NE(std::string(error.what()).find("cell 2"), std::string::npos);
  }
  cells.u_f[5] = 0.0;
  cells.phi_s[1] = 1.5;
  EXPECT_THROW(cells.exchange(*law, 1e-3), NumericalError);
  cells.phi_s[1] = 1.0 + 2.2e-16;  // a full cell after a consistent map between grids
  EXPECT_NO_THROW(cells.exchange(*law, 1e-3));
  cells.phi_s[1] = 0.4;
  cells.u_s.pop_back();
  EXPECT_THROW(cells.exchange(*law, 1e-3), std::invalid_argument);

  const auto per_cell = make_drag_law(
      YAML::Load("{law: kozeny_carman, permeability: field, fluid_viscosity: 1.0e-3}"), "drag");
  Cells other(4, 2);
  EXPECT_THROW(other.exchange(*per_cell, 1e-3), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::exchange

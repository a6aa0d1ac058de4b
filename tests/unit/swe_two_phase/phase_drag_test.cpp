#include "swe/two_phase/phase_drag.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "input_error.hpp"

namespace swe {
namespace {

constexpr double rho_f = 1000.0, dry = 1e-6, area = 4.0;

// n cells of varied depths, densities, shares and velocities, both phases present.
struct Cells {
  std::vector<double> h, hu, hv, impulse_x, impulse_y;
  SolidLayer layer;

  explicit Cells(std::size_t n) : layer(empty_solid_layer(n, 2000.0)) {
    for (std::size_t c = 0; c < n; ++c) {
      const double s = static_cast<double>(c);
      h.push_back(0.05 + 0.37 * std::fmod(1.3 * s, 2.1));
      hu.push_back(h.back() * (1.7 * std::sin(0.9 * s)));
      hv.push_back(h.back() * (-0.8 * std::cos(1.7 * s)));
      layer.depth[c] = 0.02 + 0.5 * std::fmod(0.7 * s, 1.9);
      layer.velocity_x[c] = 2.3 * std::cos(1.1 * s);
      layer.velocity_y[c] = 0.4 * std::sin(2.9 * s);
      layer.density[c] = 1100.0 + 1500.0 * std::fmod(0.31 * s, 1.0);
      layer.structured_share[c] = std::fmod(0.23 * s, 1.0);
    }
    impulse_x.assign(n, 0.0);
    impulse_y.assign(n, 0.0);
  }

  void exchange(const TwoPhaseParameters& p, double dt) {
    exchange_momentum(p, rho_f, dry, area, dt, h, hu, hv, layer, impulse_x, impulse_y);
  }
  // Momentum of both phases in cell c along x or y [kg m/s].
  double momentum(std::size_t c, int axis) const {
    const double q = axis == 0 ? hu[c] : hv[c];
    const double u = axis == 0 ? layer.velocity_x[c] : layer.velocity_y[c];
    return (rho_f * q + layer.density[c] * layer.depth[c] * u) * area;
  }
  double scale(std::size_t c, int axis) const {
    const double q = axis == 0 ? hu[c] : hv[c];
    const double u = axis == 0 ? layer.velocity_x[c] : layer.velocity_y[c];
    return (std::abs(rho_f * q) + std::abs(layer.density[c] * layer.depth[c] * u)) * area;
  }
};

TEST(SwePhaseDrag, TheCellMixtureHasTheLayersBulkDensityAndFractions) {
  TwoPhaseParameters p;
  const double h_s = 0.3, h_f = 0.9, rho_c = 1900.0;
  const auto m = cell_mixture(h_s, h_f, rho_c, 0.4, p, rho_f);
  const double error = std::max({std::abs(m.confined_density() - rho_c) / rho_c,
                                 std::abs(m.confined_fraction() - h_s / (h_s + h_f)),
                                 std::abs(m.free_fluid_fraction() - h_f / (h_s + h_f))});
  fmt::print(
      "mixture: rho_c, alpha_c, alpha_u from the layer: max relative error {:.2e} "
      "(tolerance 1e-14)\n",
      error);
  EXPECT_LE(error, 1e-14);
  EXPECT_NO_THROW(cosim::exchange::check(m));
  EXPECT_EQ(m.structured_solid_share, 0.4);
}

TEST(SwePhaseDrag, RefusesABulkDensityOutsideFluidToGrains) {
  TwoPhaseParameters p;
  for (double rho_c : {900.0, 1000.0, 2700.0}) {
    const std::string message = cosim::testing::input_error_message(
        [&] { (void)cell_mixture(0.3, 0.9, rho_c, 0.4, p, rho_f); });
    EXPECT_NE(message.find("bulk density"), std::string::npos) << message;
  }
  Cells cells(4);
  cells.layer.density[2] = 3000.0;
  const std::string message = cosim::testing::input_error_message([&] { cells.exchange(p, 0.1); });
  EXPECT_NE(message.find("cell 2"), std::string::npos) << message;
}

TEST(SwePhaseDrag, KeepsTheMomentumOfEveryCellToRoundOff) {
  double worst = 0.0, worst_impulse = 0.0;
  for (double j : {1.0, 1.5, 2.0})
    for (bool virtual_mass : {false, true})
      for (double dt : {1e-3, 1.0, 1e3}) {
        TwoPhaseParameters p;
        p.drag.exponent = j;
        p.virtual_mass = virtual_mass;
        Cells cells(40);
        const Cells before = cells;
        cells.exchange(p, dt);
        for (std::size_t c = 0; c < 40; ++c)
          for (int axis = 0; axis < 2; ++axis) {
            const double s = std::max(before.scale(c, axis), 1e-300);
            worst =
                std::max(worst, std::abs(cells.momentum(c, axis) - before.momentum(c, axis)) / s);
            // the impulse is the solids' change of momentum
            const double solid_change =
                cells.layer.density[c] * cells.layer.depth[c] * area *
                (axis == 0 ? cells.layer.velocity_x[c] - before.layer.velocity_x[c]
                           : cells.layer.velocity_y[c] - before.layer.velocity_y[c]);
            const double impulse = axis == 0 ? cells.impulse_x[c] : cells.impulse_y[c];
            worst_impulse = std::max(worst_impulse, std::abs(impulse - solid_change) / s);
          }
        // the drag acted: relative velocities shrank
        double changed = 0.0;
        for (std::size_t c = 0; c < 40; ++c)
          changed = std::max(changed, std::abs(cells.impulse_x[c]));
        EXPECT_GT(changed, 0.0);
      }
  fmt::print(
      "drag exchange, 40 cells x j in {{1, 1.5, 2}} x virtual mass x dt in {{1e-3, 1, "
      "1e3}} s: max relative change of a cell's momentum {:.2e}, impulse vs solids' "
      "momentum change {:.2e} (tolerance 1e-13)\n",
      worst, worst_impulse);
  EXPECT_LE(worst, 1e-13);
  EXPECT_LE(worst_impulse, 1e-13);
}

TEST(SwePhaseDrag, ReducesTheRelativeVelocityWithoutReversingIt) {
  TwoPhaseParameters p;
  Cells cells(40);
  const Cells before = cells;
  cells.exchange(p, 0.5);
  for (std::size_t c = 0; c < 40; ++c) {
    const double w0x = before.hu[c] / before.h[c] - before.layer.velocity_x[c];
    const double w1x = cells.hu[c] / cells.h[c] - cells.layer.velocity_x[c];
    EXPECT_LE(std::abs(w1x), std::abs(w0x) * (1.0 + 1e-12)) << "cell " << c;
    EXPECT_GE(w1x * w0x, 0.0) << "cell " << c;
  }
}

TEST(SwePhaseDrag, LeavesCellsWithoutBothPhasesAlone) {
  TwoPhaseParameters p;
  Cells cells(6);
  cells.h[1] = 0.5 * dry;  // dry fluid
  cells.hu[1] = cells.hv[1] = 0.0;
  cells.layer.depth[3] = 0.0;  // no solids
  cells.layer.depth[4] = dry;  // solids at the dry depth: absent
  const Cells before = cells;
  cells.exchange(p, 1.0);
  for (std::size_t c : {1u, 3u, 4u}) {
    EXPECT_EQ(cells.hu[c], before.hu[c]);
    EXPECT_EQ(cells.hv[c], before.hv[c]);
    EXPECT_EQ(cells.layer.velocity_x[c], before.layer.velocity_x[c]);
    EXPECT_EQ(cells.layer.velocity_y[c], before.layer.velocity_y[c]);
    EXPECT_EQ(cells.impulse_x[c], 0.0);
    EXPECT_EQ(cells.impulse_y[c], 0.0);
  }
  EXPECT_NE(cells.layer.velocity_x[0], before.layer.velocity_x[0]);
}

TEST(SwePhaseDrag, ReadsTheGrainSizePerCellWhenGiven) {
  TwoPhaseParameters p;
  Cells plain(8), same(8), finer(8);
  same.layer.grain_size.assign(8, p.drag.grain_size);
  finer.layer.grain_size.assign(8, p.drag.grain_size);
  finer.layer.grain_size[5] = 1e-5;
  plain.exchange(p, 0.1);
  same.exchange(p, 0.1);
  finer.exchange(p, 0.1);
  EXPECT_EQ(plain.impulse_x, same.impulse_x);
  EXPECT_EQ(plain.impulse_x[4], finer.impulse_x[4]);
  EXPECT_NE(plain.impulse_x[5], finer.impulse_x[5]);
}

}  // namespace
}  // namespace swe

#include "cosim/exchange/drag_relaxation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim::exchange {
namespace {

DragRelaxation linear_cell(double drag) {
  DragRelaxation cell;
  cell.solid_weight = 0.4 * 2650;
  cell.fluid_weight = 0.6 * 1000;
  cell.drag_coefficient = drag;
  return cell;
}

double mu(const DragRelaxation& cell) {
  return 1 / cell.solid_weight + 1 / cell.fluid_weight;
}

TEST(DragRelaxation, ALinearDragDecaysTheRelativeVelocityExponentially) {
  const DragRelaxation cell = linear_cell(2e3);
  std::array<double, 2> u_c{1.0, 0.5};
  std::array<double, 2> u_u{-1.0, 2.5};
  std::array<double, 2> impulse{};
  const double dt = 1e-3;
  relax_drag(cell, dt, u_c, u_u, impulse);
  const double factor = std::exp(-cell.drag_coefficient * mu(cell) * dt);
  EXPECT_NEAR(u_u[0] - u_c[0], -2.0 * factor, 1e-14);
  EXPECT_NEAR(u_u[1] - u_c[1], 2.0 * factor, 1e-14);
  // the solid's momentum grew by the impulse, the fluid's fell by as much
  EXPECT_NEAR(cell.solid_weight * (u_c[0] - 1.0), impulse[0], 1e-12);
  EXPECT_NEAR(cell.fluid_weight * (u_u[0] + 1.0), -impulse[0], 1e-12);
  const double momentum = cell.solid_weight * (u_c[1] - 0.5) + cell.fluid_weight * (u_u[1] - 2.5);
  EXPECT_NEAR(momentum, 0.0, 1e-12);
}

TEST(DragRelaxation, AQuadraticDragFollowsItsClosedForm) {
  DragRelaxation cell = linear_cell(50.0);
  cell.exponent = 2;
  std::array<double, 1> u_c{0.0};
  std::array<double, 1> u_u{3.0};
  const double dt = 0.02;
  relax_drag(cell, dt, u_c, u_u);
  const double a = cell.drag_coefficient * mu(cell);
  EXPECT_NEAR(u_u[0] - u_c[0], 3.0 / (1.0 + a * 3.0 * dt), 1e-13);
}

TEST(DragRelaxation, VirtualMassSlowsTheRelaxationByOnePlusVMu) {
  DragRelaxation cell = linear_cell(2e3);
  cell.virtual_mass = 0.4 * 1000 * 1.5;
  std::array<double, 1> u_c{0.0};
  std::array<double, 1> u_u{1.0};
  const double dt = 1e-3;
  relax_drag(cell, dt, u_c, u_u);
  const double rate = cell.drag_coefficient * mu(cell) / (1 + cell.virtual_mass * mu(cell));
  EXPECT_NEAR(u_u[0] - u_c[0], std::exp(-rate * dt), 1e-14);
  EXPECT_NEAR(cell.solid_weight * u_c[0] + cell.fluid_weight * (u_u[0] - 1.0), 0.0, 1e-12);
}

TEST(DragRelaxation, AnInfiniteDragLocksThePhasesAtTheirMomentumWeightedVelocity) {
  const DragRelaxation cell = linear_cell(std::numeric_limits<double>::infinity());
  std::array<double, 1> u_c{2.0};
  std::array<double, 1> u_u{-1.0};
  relax_drag(cell, 1e-3, u_c, u_u);
  const double mean =
      (cell.solid_weight * 2.0 - cell.fluid_weight) / (cell.solid_weight + cell.fluid_weight);
  EXPECT_NEAR(u_c[0], mean, 1e-14);
  EXPECT_NEAR(u_u[0], mean, 1e-14);
}

TEST(DragRelaxation, AnAbsentPhaseOrNoDragChangesNothing) {
  DragRelaxation no_solid = linear_cell(1e3);
  no_solid.solid_weight = 0;
  DragRelaxation no_fluid = linear_cell(1e3);
  no_fluid.fluid_weight = 0;
  for (const DragRelaxation& cell : {linear_cell(0.0), no_solid, no_fluid}) {
    std::array<double, 1> u_c{2.0};
    std::array<double, 1> u_u{-1.0};
    std::array<double, 1> impulse{7.0};
    relax_drag(cell, 1.0, u_c, u_u, impulse);
    EXPECT_EQ(u_c[0], 2.0);
    EXPECT_EQ(u_u[0], -1.0);
    EXPECT_EQ(impulse[0], 0.0);
  }
}

TEST(DragRelaxation, ATinyStepTakesAwayExactlyRateTimesStep) {
  for (const double exponent : {1.0, 1.5, 2.0}) {
    const double fraction = relaxed_fraction(1e3, exponent, 1.0, 1e-15);
    EXPECT_NEAR(fraction / 1e-12, 1.0, 1e-9) << "j " << exponent;
  }
}

TEST(DragRelaxation, RefusesBadInput) {
  std::array<double, 2> u_c{0.0, 0.0};
  std::array<double, 2> u_u{1.0, 0.0};
  std::array<double, 1> short_vector{0.0};
  EXPECT_THROW(relax_drag(linear_cell(1.0), 1.0, u_c, short_vector), std::invalid_argument);
  EXPECT_THROW(relax_drag(linear_cell(-1.0), 1.0, u_c, u_u), std::invalid_argument);
  EXPECT_THROW(relax_drag(linear_cell(std::nan("")), 1.0, u_c, u_u), std::invalid_argument);
  EXPECT_THROW(relax_drag(linear_cell(1.0), -1.0, u_c, u_u), std::invalid_argument);
  DragRelaxation sub_linear = linear_cell(1.0);
  sub_linear.exponent = 0.5;
  EXPECT_THROW(relax_drag(sub_linear, 1.0, u_c, u_u), std::invalid_argument);
  u_u[1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(relax_drag(linear_cell(1.0), 1.0, u_c, u_u), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::exchange

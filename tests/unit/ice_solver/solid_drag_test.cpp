// The fluid-solid drag solved inside the ICE step (IceSolver::set_solid_drag,
// the coupler's `solved_by: fluid`): the momentum the fluid loses is the
// solid's impulse to round-off, uniform relaxation follows the implicit
// two-material exchange (Tran et al., MPMICE, eq. 131) step by step,
// steady flow through a held porous column is Darcy's whatever the step, the
// pressure's force on the solid is its buoyancy at rest, and bad input is
// refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "cosim/error.hpp"
#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {
namespace {

std::vector<FluidMaterial> water() {
  return {{"water", std::make_shared<LinearWater>(LinearWaterParameters{}), 0.0, 0.0}};
}

template <int Dim>
CellGrid<Dim> strip(int cells, double length) {
  typename CellGrid<Dim>::CellIndex count;
  count.fill(1);
  count[0] = cells;
  typename CellGrid<Dim>::Point spacing = CellGrid<Dim>::Point::Constant(length / cells);
  return CellGrid<Dim>(CellGrid<Dim>::Point::Zero(), spacing, count);
}

template <int Dim>
FluidState<Dim> still_water(const CellGrid<Dim>& grid, double porosity, double velocity = 0.0) {
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  FluidState<Dim> state;
  state.materials.resize(1);
  MaterialState<Dim>& m = state.materials[0];
  m.bulk_density.assign(cells, 999.8 * porosity);
  m.temperature.assign(cells, 283.15);
  for (auto& u : m.velocity) u.assign(cells, 0.0);
  m.velocity[0].assign(cells, velocity);
  state.porosity.assign(cells, porosity);
  state.pressure.assign(cells, 101325.0);
  return state;
}

std::array<SideCondition, 2> open_ends(double inlet, double outlet) {
  SideCondition a, b;
  a.type = b.type = SideType::fixed_pressure;
  a.pressure = inlet;
  b.pressure = outlet;
  return {a, b};
}

TEST(IceSolidDrag, UniformRelaxationIsTheImplicitExchangeAndKeepsMomentum) {
  // One row of cells between walls, the water moving across the row (in y):
  // nothing but the drag changes its y momentum.
  const CellGrid<2> grid(CellGrid<2>::Point::Zero(), CellGrid<2>::Point(0.125, 0.125), {8, 1});
  const double n = 0.4, v0 = 0.3, k = 2.0e5, solid_density = 1590.0, dt = 1e-3;
  FluidState<2> state = still_water(grid, n);
  state.materials[0].velocity[1].assign(8, v0);
  IceSolver<2> solver(grid, water(), ExchangeCoefficients::none(1), {}, Eigen::Vector2d::Zero(),
                      state);
  const std::size_t cells = 8;
  solver.set_porous_medium(std::vector<double>(cells, n),
                           {CellField(cells, 0.0), CellField(cells, 0.0)});
  solver.set_solid_drag(std::vector<double>(cells, k), std::vector<double>(cells, solid_density));
  const double fluid_density = solver.state().materials[0].bulk_density[0];
  const double volume = grid.cell_volume();
  const double before = solver.totals()[0].momentum[1];
  double impulse_total = 0.0, relative = v0, worst = 0.0;
  std::vector<double> impulse(2 * cells);
  for (int step = 0; step < 10; ++step) {
    ASSERT_TRUE(solver.advance(dt).accepted);
    solver.take_solid_impulse(impulse);
    for (std::size_t c = 0; c < cells; ++c) impulse_total += impulse[2 * c + 1];
    // eq. 131: U_f - U_s shrinks by 1 + dt K (1/rhobar_f + 1/rhobar_s) per step.
    relative /= 1.0 + dt * k * (1.0 / fluid_density + 1.0 / solid_density);
    const double solid_velocity = impulse_total / (solid_density * volume * cells);
    const double fluid = solver.state().materials[0].velocity[1][3];
    worst = std::max(worst, std::abs((fluid - solid_velocity) / relative - 1.0));
  }
  const double lost = before - solver.totals()[0].momentum[1];
  fmt::print(
      "momentum lost by the fluid {:.6e} vs impulse to the solid {:.6e}; relative velocity vs "
      "eq. 131: worst {:.1e}\n",
      lost, impulse_total, worst);
  EXPECT_LT(std::abs(lost - impulse_total), 1e-12 * std::abs(lost));
  EXPECT_LT(worst, 1e-9);
}

// 20 cells over 2 m, the middle 10 porous (n = 0.4) around a held solid
// with drag K, dp = 50 kPa across: the state after 0.5 s of steps dt
// (steady), with the drag received for a fluid of `drag_viscosity`.
constexpr double column_porosity = 0.4, column_drag = 1.62e5, column_dp = 5.0e4;

std::unique_ptr<IceSolver<1>> darcy_column(const std::vector<FluidMaterial>& materials, double dt,
                                           double drag_viscosity = 0.0) {
  const CellGrid<1> grid = strip<1>(20, 2.0);
  auto solver = std::make_unique<IceSolver<1>>(
      grid, materials, ExchangeCoefficients::none(1), open_ends(101325.0 + column_dp, 101325.0),
      Eigen::Matrix<double, 1, 1>::Zero(), still_water(grid, 1.0));
  std::vector<double> porosity(20, 1.0), drag(20, 0.0), density(20, 0.0);
  for (std::size_t c = 5; c < 15; ++c) {
    porosity[c] = column_porosity;
    drag[c] = column_drag;
    density[c] = 1e30;  // held
  }
  solver->set_porous_medium(porosity, {CellField(20, 0.0)}, PorosityChange::fill_pores);
  solver->set_drag_viscosity(drag_viscosity);
  solver->set_solid_drag(drag, density);
  for (double t = 0.0; t < 0.5; t += dt) {
    if (!solver->advance(dt).accepted) return nullptr;
  }
  return solver;
}

TEST(IceSolidDrag, SteadyFlowThroughAHeldColumnIsDarcysAtAnyStep) {
  const double n = column_porosity;
  const double darcy = n * column_dp / (column_drag * 1.0);  // n grad p = K U_f, interstitial
  for (double dt : {1e-3, 2e-2}) {
    const auto solver = darcy_column(water(), dt);
    ASSERT_TRUE(solver);
    const double u = solver->state().materials[0].velocity[0][10];
    const double flux = solver->face_velocity(0)[0][3];  // free water upstream
    fmt::print("dt {:.0e}: U_f {:.6f} vs Darcy {:.6f} ({:+.2e}); upstream flux vs n U_f {:+.2e}\n",
               dt, u, darcy, u / darcy - 1.0, flux / (n * darcy) - 1.0);
    EXPECT_NEAR(u / darcy, 1.0, 2e-3);
    EXPECT_NEAR(flux / (n * darcy), 1.0, 2e-3);
  }
}

TEST(IceSolidDrag, PressureForceOnASolidAtRestIsItsBuoyancy) {
  const CellGrid<2> grid(CellGrid<2>::Point::Zero(), CellGrid<2>::Point(0.1, 0.1), {2, 10});
  const double n = 0.4, g = 9.81;
  FluidState<2> state = still_water(grid, n);
  // Hydrostatic: the water's density from its pressure, rho_ref (1 + (P - P_ref) / K).
  for (int c = 0; c < grid.cell_count(); ++c) {
    const auto i = static_cast<std::size_t>(c);
    state.pressure[i] = 101325.0 + 999.8 * g * (1.0 - grid.cell_centre(c)[1]);
    state.materials[0].bulk_density[i] = n * 999.8 * (1.0 + (state.pressure[i] - 101325.0) / 2.0e9);
  }
  std::array<SideCondition, 4> sides{};
  sides[3].type = SideType::fixed_pressure;
  sides[3].pressure = 101325.0;
  IceSolver<2> solver(grid, water(), ExchangeCoefficients::none(1), sides, Eigen::Vector2d(0.0, -g),
                      state);
  std::vector<double> drag(20, 1e6), density(20, 1590.0);
  solver.set_porous_medium(std::vector<double>(20, n), {CellField(20, 0.0), CellField(20, 0.0)});
  solver.set_solid_drag(drag, density);
  for (int step = 0; step < 5; ++step) ASSERT_TRUE(solver.advance(1e-3).accepted);
  std::vector<double> force(40);
  solver.solid_pressure_force(force);
  const double rho = solver.state().materials[0].density[5];
  const double buoyancy = (1.0 - n) * rho * g * grid.cell_volume();
  double worst = 0.0;
  for (int c = 0; c < 20; ++c) {
    worst = std::max(worst, std::abs(force[2 * static_cast<std::size_t>(c) + 1] / buoyancy - 1.0));
    EXPECT_NEAR(force[2 * static_cast<std::size_t>(c)], 0.0, 1e-9 * buoyancy);
  }
  fmt::print("pressure force on the solid vs its buoyancy: worst {:.1e}\n", worst);
  EXPECT_LT(worst, 1e-4);
}

TEST(IceSolidDrag, AHeldSolidMovesNoPorosityAcrossItsFaces) {
  // A strip between walls: the left half an impermeable held solid (n = 0.3,
  // K = 1e15) with the velocity 0.2 m/s the solid solver sent (a shaking
  // table), the right half a porous solid that is not held. Within the step
  // no solid crosses the held cells' faces: their porosity stays as set (the
  // upwind flux would move 0.7 x 0.2 x dt / dx of solid out of the last one
  // into the first free cell); between the free cells the solid still moves.
  const CellGrid<1> grid = strip<1>(8, 1.0);
  SideCondition wall;
  IceSolver<1> solver(grid, water(), ExchangeCoefficients::none(1), {wall, wall},
                      Eigen::Matrix<double, 1, 1>::Zero(), still_water(grid, 1.0));
  std::vector<double> porosity(8), drag(8), density(8);
  CellField velocity(8, 0.0);
  for (std::size_t c = 0; c < 8; ++c) {
    const bool is_held = c < 4;
    porosity[c] = is_held ? 0.3 : 0.4 + 0.05 * static_cast<double>(c - 4);
    drag[c] = is_held ? 1e15 : 1e5;
    density[c] = is_held ? 1e30 : 1590.0;
    velocity[c] = is_held ? 0.2 : 0.1;
  }
  solver.set_porous_medium(porosity, {velocity}, PorosityChange::fill_pores);
  solver.set_solid_drag(drag, density);
  const double dt = 1e-3;
  ASSERT_TRUE(solver.advance(dt).accepted);
  const CellField& n = solver.state().porosity;
  for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(n[c], porosity[c]) << "cell " << c;
  // The first free cell only loses solid through its free side (upwind
  // 1 - 0.4 at 0.1 m/s); between the free cells the upwind flux moves it on.
  const double dx = grid.spacing()[0];
  EXPECT_NEAR(n[4] - porosity[4], dt * 0.1 * (1.0 - porosity[4]) / dx, 1e-12);
  EXPECT_NEAR(n[5] - porosity[5], -dt * 0.1 * (porosity[5] - porosity[4]) / dx, 1e-12);
}

TEST(IceSolidDrag, ATraceOfAirInTheSoilKeepsItsTemperature) {
  // Water with a trace of air (volume fraction 1e-6) pushed by 0.5 atm
  // through a held porous column (Darcy flow) whose pores open and close by
  // 1e-6 from step to step, as a coupled solid's porosity arrives a little
  // off the one the fluid moved. The trace's share of the pressure work is
  // not its own compression: without a guard it reaches 3.2 times the
  // water's temperature in these 400 steps (and in coupled runs cools to no
  // energy at all, or heats by orders of magnitude). It stays within a factor
  // of two of the water's and no step is refused.
  const CellGrid<1> grid = strip<1>(20, 2.0);
  std::vector<FluidMaterial> materials = water();
  materials.push_back({"air", std::make_shared<IdealGas>(287.0, 717.5), 0.0, 0.0});
  FluidState<1> state = still_water(grid, 1.0);
  state.materials.resize(2);
  MaterialState<1>& air = state.materials[1];
  air.bulk_density.assign(20, 1e-6 * 1.2);
  air.temperature.assign(20, 283.15);
  air.velocity[0].assign(20, 0.0);
  for (double& rho : state.materials[0].bulk_density) rho *= 1.0 - 1e-6;
  ExchangeCoefficients exchange = ExchangeCoefficients::none(2);
  exchange.set(0, 1, 1e15, 0.0);
  IceSolver<1> solver(grid, materials, exchange, open_ends(151325.0, 101325.0),
                      Eigen::Matrix<double, 1, 1>::Zero(), state);
  std::vector<double> porosity(20, 1.0), drag(20, 0.0), density(20, 0.0);
  for (std::size_t c = 5; c < 15; ++c) {
    porosity[c] = 0.4;
    drag[c] = 1.62e5;
    density[c] = 1e30;
  }
  solver.set_porous_medium(porosity, {CellField(20, 0.0)}, PorosityChange::fill_pores);
  solver.set_solid_drag(drag, density);
  double coldest = 1.0, hottest = 1.0;
  for (int step = 0; step < 400; ++step) {
    for (std::size_t c = 5; c < 15; ++c) porosity[c] = step % 2 == 0 ? 0.400001 : 0.399999;
    solver.set_porous_medium(porosity, {CellField(20, 0.0)});
    solver.set_solid_drag(drag, density);
    ASSERT_TRUE(solver.advance(1e-3).accepted) << "step " << step;
    for (std::size_t c = 0; c < 20; ++c) {
      const double ratio =
          solver.state().materials[1].temperature[c] / solver.state().materials[0].temperature[c];
      coldest = std::min(coldest, ratio);
      hottest = std::max(hottest, ratio);
    }
  }
  fmt::print("trace air / water temperature over 400 steps: {:.3f} ... {:.3f}\n", coldest, hottest);
  EXPECT_GE(coldest, 0.5);
  EXPECT_LE(hottest, 2.0);
}

TEST(IceSolidDrag, BadDragInputIsRefused) {
  const CellGrid<1> grid = strip<1>(4, 1.0);
  SideCondition wall;
  IceSolver<1> solver(grid, water(), ExchangeCoefficients::none(1), {wall, wall},
                      Eigen::Matrix<double, 1, 1>::Zero(), still_water(grid, 1.0));
  EXPECT_THROW(solver.set_solid_drag(std::vector<double>(3, 1.0), std::vector<double>(4, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(
      solver.set_solid_drag(std::vector<double>{1.0, -1.0, 1.0, 1.0}, std::vector<double>(4, 1.0)),
      cosim::NumericalError);
  EXPECT_THROW(
      solver.set_solid_drag(std::vector<double>(4, 1.0), std::vector<double>{1.0, NAN, 1.0, 1.0}),
      cosim::NumericalError);
  std::vector<double> impulse(3);
  EXPECT_THROW(solver.take_solid_impulse(impulse), std::invalid_argument);
  solver.set_solid_drag({}, {});
  EXPECT_FALSE(solver.has_solid_drag());
}

TEST(IceSolidDrag, EachFluidTakesTheDragScaledByItsViscosity) {
  // The Darcy column above, the drag received for a fluid of 1e-3 Pa s and
  // the water twice as viscous: Darcy's velocity halves, at any step.
  const double mu_drag = 1.0e-3, mu = 2.0e-3;
  const double darcy = column_porosity * column_dp / (column_drag * mu / mu_drag * 1.0);
  std::vector<FluidMaterial> viscous = water();
  viscous[0].viscosity = mu;
  for (double dt : {1e-3, 2e-2}) {
    const auto solver = darcy_column(viscous, dt, mu_drag);
    ASSERT_TRUE(solver);
    const double u = solver->state().materials[0].velocity[0][10];
    fmt::print(
        "dt {:.0e}: U_f {:.6f} vs Darcy's with K mu / mu_drag {:.6f} ({:+.2e}, tolerance "
        "2e-3)\n",
        dt, u, darcy, u / darcy - 1.0);
    EXPECT_NEAR(u / darcy, 1.0, 2e-3);
  }
}

TEST(IceSolidDrag, ADragViscosityNeedsEveryFluidViscous) {
  const CellGrid<1> grid = strip<1>(4, 1.0);
  IceSolver<1> solver(grid, water(), ExchangeCoefficients::none(1), {},
                      Eigen::Matrix<double, 1, 1>::Zero(), still_water(grid, 1.0));
  EXPECT_THROW(solver.set_drag_viscosity(1e-3), std::invalid_argument);  // water() is inviscid
  EXPECT_THROW(solver.set_drag_viscosity(-1.0), std::invalid_argument);
  EXPECT_THROW(solver.set_drag_viscosity(NAN), std::invalid_argument);
  EXPECT_NO_THROW(solver.set_drag_viscosity(0.0));
}

}  // namespace
}  // namespace ice

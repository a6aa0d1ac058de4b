// How ICE takes a porous medium that changed between two reads
// (IceSolver::set_porous_medium): displaced, the pores the solid closed
// squeeze their water out through the open top in the next step, with the
// pressure of that flow; compressed, the same water is squeezed in place,
// K dn / n at once, and the step starts from that pressure. Either way every
// cell's fluids fill its pores.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ice/eos/linear_water.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {
namespace {

constexpr double atmosphere = 101325.0;

struct Squeezed {
  double pressure_rise;  // [Pa] in the squeezed cell after the step
  double water_lost;     // [kg/m2] through the open top
  double worst_closure;  // max |sum of fluid volume fractions - porosity|
};

// A 0.1 m column of 10 cells of water in pores n = 0.6, no gravity, a wall
// below and the atmosphere above; the bottom cell's solid grows by dn.
Squeezed squeeze(PorosityChange change, double dn, double dt) {
  const CellGrid<1> grid(CellGrid<1>::Point::Zero(), CellGrid<1>::Point::Constant(0.01), {10});
  const double n = 0.6;
  FluidState<1> state;
  state.materials.resize(1);
  MaterialState<1>& water = state.materials[0];
  water.bulk_density.assign(10, 999.8 * n);
  water.temperature.assign(10, 283.15);
  water.velocity[0].assign(10, 0.0);
  state.porosity.assign(10, n);
  state.pressure.assign(10, atmosphere);
  std::array<SideCondition, 2> sides{};
  sides[1].type = SideType::fixed_pressure;
  sides[1].pressure = atmosphere;
  IceSolver<1> solver(
      grid, {{"water", std::make_shared<LinearWater>(LinearWaterParameters{}), 0.0, 0.0}},
      ExchangeCoefficients::none(1), sides, Eigen::Matrix<double, 1, 1>::Zero(), state);
  const double before = solver.totals()[0].mass;
  std::vector<double> porosity(10, n);
  porosity[0] = n - dn;
  solver.set_porous_medium(porosity, {CellField(10, 0.0)}, change);
  EXPECT_TRUE(solver.advance(dt).accepted);
  Squeezed out{solver.state().pressure[0] - atmosphere, before - solver.totals()[0].mass, 0.0};
  for (std::size_t c = 0; c < 10; ++c) {
    EXPECT_DOUBLE_EQ(solver.state().porosity[c], porosity[c]) << "cell " << c;
    out.worst_closure = std::max(
        out.worst_closure, std::abs(solver.state().materials[0].volume_fraction[c] - porosity[c]));
  }
  return out;
}

TEST(IcePorousMedium, DisplacedPoresSqueezeTheirWaterOutThroughTheOpenTop) {
  // A step 15 times the time sound takes to cross the column.
  const double dn = 0.02, dt = 1e-3;
  const Squeezed displaced = squeeze(PorosityChange::displace, dn, dt);
  const Squeezed compressed = squeeze(PorosityChange::compress, dn, dt);
  const double squeezed_volume = dn * 0.01;  // [m3/m2]
  // Pushing that volume out within dt through the column's 0.1 m of pore
  // water takes a pressure of about rho L (dV / (n dt)) / dt, here 3.3e4 Pa.
  const double flow_pressure = 999.8 * 0.1 * (squeezed_volume / 0.6 / dt) / dt;
  const double stiff = 2.15e9 * dn / 0.6;  // K dn / n
  fmt::print(
      "displaced: rise {:.4g} Pa (flow scale {:.3g}), water out {:.6f} kg vs rho dV {:.6f}, "
      "closure {:.1e}; compressed: rise {:.4g} Pa (K dn / n = {:.3g}), water out {:.2e} kg\n",
      displaced.pressure_rise, flow_pressure, displaced.water_lost, 999.8 * squeezed_volume,
      displaced.worst_closure, compressed.pressure_rise, stiff, compressed.water_lost);
  EXPECT_NEAR(displaced.water_lost / (999.8 * squeezed_volume), 1.0, 0.01);
  EXPECT_LT(displaced.pressure_rise, 2.0 * flow_pressure);
  EXPECT_LT(displaced.worst_closure, 1e-6);
  // Compressed, the step starts from K dn / n and its pressure wave rings.
  EXPECT_GT(compressed.pressure_rise, 10.0 * displaced.pressure_rise);
  EXPECT_LT(compressed.worst_closure, 1e-9);
}

TEST(IcePorousMedium, AnUnchangedMediumDisplacesNothing) {
  const Squeezed s = squeeze(PorosityChange::displace, 0.0, 1e-3);
  EXPECT_LT(std::abs(s.pressure_rise), 1e-6);
  EXPECT_LT(std::abs(s.water_lost), 1e-12);
}

}  // namespace
}  // namespace ice

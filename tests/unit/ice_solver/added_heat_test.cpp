// Heat from the coupler's energy exchange (IceSolver::add_heat): shared by
// heat capacity, so water and air in a cell warm alike, and the internal
// energy grows by exactly the heat; bad heat is refused.
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

TEST(IceAddedHeat, WarmsTheMaterialsAlikeAndKeepsTheEnergy) {
  const CellGrid<1> grid(CellGrid<1>::Point::Zero(), CellGrid<1>::Point::Constant(0.1), {4});
  std::vector<FluidMaterial> materials{
      {"water", std::make_shared<LinearWater>(LinearWaterParameters{}), 0.0, 0.0},
      {"air", std::make_shared<IdealGas>(287.0, 717.5), 0.0, 0.0}};
  FluidState<1> state;
  state.materials.resize(2);
  const double fractions[] = {0.7, 0.3};
  const double densities[] = {999.8, 1.2};
  for (std::size_t m = 0; m < 2; ++m) {
    state.materials[m].bulk_density.assign(4, fractions[m] * densities[m]);
    state.materials[m].temperature.assign(4, 283.15);
    state.materials[m].velocity[0].assign(4, 0.0);
  }
  state.pressure.assign(4, 101325.0);
  SideCondition wall;
  IceSolver<1> solver(grid, materials, ExchangeCoefficients::none(2), {wall, wall},
                      Eigen::Matrix<double, 1, 1>::Zero(), state);
  const auto before = solver.totals();
  const std::vector<double> heat{100.0, -50.0, 0.0, 2000.0};
  solver.add_heat(heat);
  const auto after = solver.totals();
  const double gained = after[0].internal_energy + after[1].internal_energy -
                        before[0].internal_energy - before[1].internal_energy;
  fmt::print("internal energy gained {:.12g} J vs heat {:.12g} J\n", gained, 2050.0);
  EXPECT_NEAR(gained, 2050.0, 1e-9 * 2050.0);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(solver.state().materials[0].temperature[c],
                solver.state().materials[1].temperature[c], 1e-12);
  }
  EXPECT_GT(solver.state().materials[0].temperature[3], 283.15);
  EXPECT_LT(solver.state().materials[0].temperature[1], 283.15);
  EXPECT_THROW(solver.add_heat(std::vector<double>(3, 0.0)), std::invalid_argument);
  EXPECT_THROW(solver.add_heat(std::vector<double>{0.0, NAN, 0.0, 0.0}), cosim::NumericalError);
  EXPECT_THROW(solver.add_heat(std::vector<double>{0.0, -1e12, 0.0, 0.0}), cosim::NumericalError);
}

}  // namespace
}  // namespace ice

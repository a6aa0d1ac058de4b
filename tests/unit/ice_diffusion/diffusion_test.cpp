#include "ice/diffusion/diffusion.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace ice {
namespace {

// u_x = cos(pi y / L) between two walls (no shear on them: the mode's
// slope is zero there) decays as exp(-nu (pi / L)^2 t); forward Euler with
// a small step, second order in space. One cell across x: the flow is
// uniform along x, as between two infinite plates.
double shear_wave_error(int cells) {
  const double length = 1.0, rho = 1.0, mu = 0.01, end = 2.0;
  const CellGrid<2> grid(CellGrid<2>::Point(0.0, 0.0), CellGrid<2>::Point(0.25, length / cells),
                         {1, cells});
  const Diffusion<2> diffusion(grid, {});
  Diffusion<2>::Velocity u{make_cell_field(grid), make_cell_field(grid)};
  for (int c = 0; c < grid.cell_count(); ++c) {
    u[0][static_cast<std::size_t>(c)] =
        std::cos(std::numbers::pi * grid.cell_centre(c)[1] / length);
  }
  const CellField mu_field = make_cell_field(grid, mu), phi = make_cell_field(grid, 1.0);
  const double dt = 0.2 * diffusion_time_step(grid, mu / rho);
  const int steps = static_cast<int>(std::ceil(end / dt));
  for (int s = 0; s < steps; ++s) {
    Diffusion<2>::Velocity momentum = u;
    diffusion.add_viscous_momentum(mu_field, phi, u, end / steps, momentum);
    u = momentum;
  }
  const double decay = std::exp(-mu / rho * std::pow(std::numbers::pi / length, 2) * end);
  double error = 0.0;
  for (int c = 0; c < grid.cell_count(); ++c) {
    const double exact = decay * std::cos(std::numbers::pi * grid.cell_centre(c)[1] / length);
    error = std::max(error, std::abs(u[0][static_cast<std::size_t>(c)] - exact));
  }
  return error / decay;
}

TEST(IceDiffusion, ShearWaveDecaysAtTheViscousRateWithSecondOrder) {
  const double coarse = shear_wave_error(16);
  const double fine = shear_wave_error(32);
  fmt::print("shear wave: error {:.2e} (16 cells), {:.2e} (32 cells), order {:.2f}\n", coarse, fine,
             std::log2(coarse / fine));
  EXPECT_LE(fine, 1e-3);
  EXPECT_GT(std::log2(coarse / fine), 1.8);
}

// d/dx of (4/3) mu du/dx for u = x^2: (8/3) mu per unit volume, exactly in
// the interior cells.
TEST(IceDiffusion, NormalStressCarriesTheFourThirdsOfTheDilatation) {
  const CellGrid<1> grid(CellGrid<1>::Point(0.0), CellGrid<1>::Point(0.1), {10});
  const Diffusion<1> diffusion(grid, {});
  Diffusion<1>::Velocity u{make_cell_field(grid)};
  for (int c = 0; c < 10; ++c)
    u[0][static_cast<std::size_t>(c)] = std::pow(grid.cell_centre(c)[0], 2);
  Diffusion<1>::Velocity momentum{make_cell_field(grid)};
  diffusion.add_viscous_momentum(make_cell_field(grid, 2.0), make_cell_field(grid, 1.0), u, 1.0,
                                 momentum);
  for (int c = 1; c < 9; ++c)
    EXPECT_NEAR(momentum[0][static_cast<std::size_t>(c)], 8.0 / 3.0 * 2.0, 1e-10);
}

template <int Dim>
void expect_momentum_conserved() {
  typename CellGrid<Dim>::CellIndex cells;
  cells.fill(6);
  const CellGrid<Dim> grid(CellGrid<Dim>::Point::Zero(), CellGrid<Dim>::Point::Constant(0.1),
                           cells);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> value(0.1, 2.0);
  CellField mu = make_cell_field(grid), phi = make_cell_field(grid);
  typename Diffusion<Dim>::Velocity u, momentum;
  for (int d = 0; d < Dim; ++d) {
    u[static_cast<std::size_t>(d)] = make_cell_field(grid);
    momentum[static_cast<std::size_t>(d)] = make_cell_field(grid);
    for (auto& x : u[static_cast<std::size_t>(d)]) x = value(random) - 1.0;
  }
  for (auto& x : mu) x = value(random);
  for (auto& x : phi) x = 0.5 * value(random);
  Diffusion<Dim>(grid, {}).add_viscous_momentum(mu, phi, u, 0.01, momentum);
  for (int d = 0; d < Dim; ++d) {
    double sum = 0.0, size = 0.0;
    for (const double m : momentum[static_cast<std::size_t>(d)]) {
      sum += m;
      size += std::abs(m);
    }
    EXPECT_LE(std::abs(sum), 1e-14 * size) << Dim << "D component " << d;
    EXPECT_GT(size, 0.0);
  }
}

TEST(IceDiffusion, ViscousFluxesConserveMomentum2D) {
  expect_momentum_conserved<2>();
}
TEST(IceDiffusion, ViscousFluxesConserveMomentum3D) {
  expect_momentum_conserved<3>();
}

TEST(IceDiffusion, HeatConservesEnergyWhenInsulatedAndReachesTheLinearProfile) {
  const CellGrid<1> grid(CellGrid<1>::Point(0.0), CellGrid<1>::Point(0.05), {20});
  std::array<SideCondition, 2> insulated{};
  CellField temperature = make_cell_field(grid), energy = make_cell_field(grid);
  for (int c = 0; c < 20; ++c)
    temperature[static_cast<std::size_t>(c)] = 300.0 + 10.0 * std::sin(c);
  Diffusion<1>(grid, insulated)
      .add_heat_conduction(make_cell_field(grid, 0.6), make_cell_field(grid, 1.0), temperature, 1.0,
                           energy);
  double sum = 0.0;
  for (const double e : energy) sum += e;
  EXPECT_NEAR(sum, 0.0, 1e-10);

  std::array<SideCondition, 2> held{};
  held[0].temperature = 280.0;
  held[1].temperature = 320.0;
  const Diffusion<1> diffusion(grid, held);
  const double rho_c = 1000.0, k = 0.6;
  const double dt = 0.4 * diffusion_time_step(grid, k / rho_c);
  temperature.assign(20, 300.0);
  for (int s = 0; s < 20000; ++s) {
    std::fill(energy.begin(), energy.end(), 0.0);
    diffusion.add_heat_conduction(make_cell_field(grid, k), make_cell_field(grid, 1.0), temperature,
                                  dt, energy);
    for (std::size_t c = 0; c < 20; ++c) temperature[c] += energy[c] / rho_c;
  }
  for (int c = 0; c < 20; ++c) {
    EXPECT_NEAR(temperature[static_cast<std::size_t>(c)], 280.0 + 40.0 * grid.cell_centre(c)[0],
                1e-6);
  }
}

TEST(IceDiffusion, SmagorinskyViscosityOfAUniformShear) {
  const CellGrid<2> grid(CellGrid<2>::Point(0.0, 0.0), CellGrid<2>::Point(0.1, 0.1), {5, 5});
  std::array<CellField, 2> u{make_cell_field(grid), make_cell_field(grid)};
  const double shear = 3.0;
  for (int c = 0; c < grid.cell_count(); ++c)
    u[0][static_cast<std::size_t>(c)] = shear * grid.cell_centre(c)[1];
  CellField mu = make_cell_field(grid);
  smagorinsky_viscosity(grid, u, make_cell_field(grid, 1000.0), 0.17, mu);
  for (const double m : mu) EXPECT_NEAR(m, 1000.0 * std::pow(0.17 * 0.1, 2) * shear, 1e-12);
}

TEST(IceDiffusion, TimeStepAndBadInput) {
  const CellGrid<2> grid(CellGrid<2>::Point(0.0, 0.0), CellGrid<2>::Point(0.1, 0.2), {2, 2});
  EXPECT_TRUE(std::isinf(diffusion_time_step(grid, 0.0)));
  EXPECT_DOUBLE_EQ(diffusion_time_step(grid, 1.0), 1.0 / (2.0 * (100.0 + 25.0)));
  const Diffusion<2> diffusion(grid, {});
  Diffusion<2>::Velocity u{make_cell_field(grid), make_cell_field(grid)}, m = u;
  EXPECT_THROW(diffusion.add_viscous_momentum(make_cell_field(grid, -1.0),
                                              make_cell_field(grid, 1.0), u, 1.0, m),
               std::invalid_argument);
  EXPECT_THROW(
      diffusion.add_viscous_momentum(CellField(3, 1.0), make_cell_field(grid, 1.0), u, 1.0, m),
      std::invalid_argument);
}

}  // namespace
}  // namespace ice

#include "ice/eos/pressure_equilibration.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "eos_test_support.hpp"

namespace ice::testing {
namespace {

const IdealGas kAir = air();
const LinearWater kWater = water();
const std::array<const EquationOfState*, 2> kAirWater{&kAir, &kWater};

double sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

// The error a call throws, printed as a user reads it.
template <class Call>
PressureEquilibrationError equilibration_error(Call&& call) {
  try {
    call();
  } catch (const PressureEquilibrationError& error) {
    std::cout << "    " << error.what() << '\n';
    return error;
  }
  ADD_FAILURE() << "expected a PressureEquilibrationError";
  return PressureEquilibrationError("nothing was thrown", -1, 0.0, 0.0);
}

bool mentions(const std::exception& error, const std::string& text) {
  return std::string(error.what()).find(text) != std::string::npos;
}

// Every material's own pressure at its equilibrium density is the common
// one, to the round-off of P(rho): eps (|P| + rho dP/drho).
void expect_common_pressure(std::span<const EquationOfState* const> materials,
                            const std::vector<double>& temperature, const CellEquilibrium& cell) {
  for (std::size_t f = 0; f < materials.size(); ++f) {
    const EquationOfState& eos = *materials[f];
    const double rho = cell.density[f];
    const double own = eos.pressure(rho, temperature[f]);
    const double tolerance =
        4 * eps * (std::abs(cell.pressure) + rho * eos.dpressure_ddensity(rho, temperature[f]));
    EXPECT_NEAR(own, cell.pressure, tolerance) << eos.type();
    std::cout << "    " << eos.type() << ": P_f(rho_f, T_f) - P = " << own - cell.pressure
              << " Pa (tolerance " << tolerance << ")\n";
  }
}

TEST(PressureEquilibration, IdealGasAloneGivesRhobarRT) {
  const std::array<const EquationOfState*, 1> gas{&kAir};
  for (const double rhobar : {1.2, 1e-4, 35.0}) {
    const std::vector<double> bulk{rhobar}, temperature{300.0};
    const CellEquilibrium cell = equilibrate_pressure(gas, bulk, temperature, 1.0);
    const double expected = rhobar * 287.05 * 300.0;
    EXPECT_NEAR(cell.pressure, expected, 2 * eps * expected);
    EXPECT_NEAR(cell.volume_fraction[0], 1.0, 2 * eps);
    EXPECT_DOUBLE_EQ(cell.density[0], rhobar);
    EXPECT_DOUBLE_EQ(cell.compressibility[0], 1.0 / cell.pressure);
    std::cout << "    rhobar " << rhobar
              << ": P / (rhobar R T) - 1 = " << cell.pressure / expected - 1.0 << " (tolerance "
              << 2 * eps << ") in " << cell.iterations << " iterations (bound 4)\n";
    EXPECT_LE(cell.iterations, 4);
  }
}

TEST(PressureEquilibration, AirAndWaterFillThePoresAtOneCommonPressure) {
  const double n = 0.4;
  const std::vector<double> bulk{0.1 * 2.4, 0.3 * 1000.0}, temperature{293.15, 288.15};
  const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, n);
  const double filled = sum(cell.volume_fraction) - n;
  EXPECT_LE(std::abs(filled), 1e-12);
  EXPECT_NEAR(cell.residual, filled, 4 * eps);
  EXPECT_GT(cell.pressure, 0.0);
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_DOUBLE_EQ(cell.volume_fraction[f], bulk[f] / cell.density[f]);
    EXPECT_DOUBLE_EQ(cell.compressibility[f],
                     kAirWater[f]->compressibility(cell.density[f], temperature[f]));
  }
  expect_common_pressure(kAirWater, temperature, cell);
  std::cout << "    P = " << cell.pressure << " Pa, phi = (" << cell.volume_fraction[0] << ", "
            << cell.volume_fraction[1] << "), sum phi - n = " << filled << " (tolerance 1e-12), "
            << cell.iterations << " iterations\n";
}

// sum phi = n with phi_a = rhobar_a R T_a / P and phi_w = rhobar_w / (a + P / K),
// a = rho_w(P = 0, T_w), is the quadratic
//   (n / K) P^2 + (n a - rhobar_w - rhobar_a R T_a / K) P - rhobar_a R T_a a = 0
// with one positive root.
TEST(PressureEquilibration, AirAndWaterMatchTheQuadraticSolvedByHand) {
  const double n = 0.35, rhobar_a = 0.05 * 3.1, rhobar_w = 0.3 * 1000.4, T_a = 300.0, T_w = 278.15;
  const double K = kWater.stiffness();
  const double a = kWater.density(0.0, T_w);
  const double RT = kAir.gas_constant() * T_a;
  const double A = n / K, B = n * a - rhobar_w - rhobar_a * RT / K, C = -rhobar_a * RT * a;
  const double q = -0.5 * (B + std::copysign(std::sqrt(B * B - 4 * A * C), B));
  const double expected = B > 0 ? C / q : q / A;

  const std::vector<double> bulk{rhobar_a, rhobar_w}, temperature{T_a, T_w};
  const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, n);
  const double error = std::abs(cell.pressure / expected - 1.0);
  EXPECT_LE(error, 1e-12);
  EXPECT_NEAR(cell.volume_fraction[0], rhobar_a * RT / expected, 1e-14);
  std::cout << "    P = " << cell.pressure << " Pa, by hand " << expected << " Pa, rel. error "
            << error << " (tolerance 1e-12)\n";
}

TEST(PressureEquilibration, ConvergesInFewIterations) {
  const std::vector<double> bulk{0.1 * 2.4, 0.3 * 1000.0}, temperature{293.15, 288.15};
  const double root = equilibrate_pressure(kAirWater, bulk, temperature, 0.4).pressure;
  // From the previous step's pressure (within 10 %) and from one atmosphere.
  for (const double guess : {1.1 * root, 0.9 * root, one_atmosphere}) {
    const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, 0.4, guess);
    EXPECT_LE(cell.iterations, 6) << "guess " << guess;
    std::cout << "    guess " << guess << " Pa: " << cell.iterations << " iterations (bound 6)\n";
  }
  // Far guesses: above (the water-dominated tangent points at a tension the
  // air forbids, so bisection halves the way down) and below every
  // admissible pressure.
  for (const double guess : {1e10, 2e7, -1e12}) {
    const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, 0.4, guess);
    EXPECT_NEAR(cell.pressure, root, 1e-12 * root);
    EXPECT_LE(cell.iterations, 25) << "guess " << guess;
    std::cout << "    guess " << guess << " Pa: " << cell.iterations << " iterations (bound 25)\n";
  }
}

TEST(PressureEquilibration, IdealGasKeepsAPositivePressureFromAFarGuess) {
  const std::array<const EquationOfState*, 1> gas{&kAir};
  const std::vector<double> bulk{1e-3}, temperature{250.0};
  const CellEquilibrium cell = equilibrate_pressure(gas, bulk, temperature, 0.2, 1e9);
  const double expected = 1e-3 * 287.05 * 250.0 / 0.2;
  EXPECT_NEAR(cell.pressure, expected, 4 * eps * expected);
  EXPECT_LE(cell.iterations, 3);
  std::cout << "    from 1e9 Pa to " << cell.pressure << " Pa in " << cell.iterations
            << " iterations\n";
}

TEST(PressureEquilibration, WaterAloneMayBeInTension) {
  const std::array<const EquationOfState*, 1> liquid{&kWater};
  const std::vector<double> bulk{0.5 * 999.0}, temperature{283.15};
  const CellEquilibrium cell = equilibrate_pressure(liquid, bulk, temperature, 0.5);
  EXPECT_DOUBLE_EQ(cell.density[0], 999.0);
  EXPECT_LT(cell.pressure, 0.0);
  EXPECT_GT(cell.pressure, kWater.minimum_pressure(283.15));
  expect_common_pressure(liquid, temperature, cell);
}

TEST(PressureEquilibration, AnAbsentMaterialGetsItsDensityButNoVolume) {
  const std::vector<double> bulk{0.0, 0.4 * 1001.0}, temperature{290.0, 283.15};
  const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, 0.4);
  EXPECT_EQ(cell.volume_fraction[0], 0.0);
  EXPECT_DOUBLE_EQ(cell.density[1], 1001.0);
  EXPECT_DOUBLE_EQ(cell.density[0], cell.pressure / (287.05 * 290.0));
  expect_common_pressure(kAirWater, temperature, cell);
}

TEST(PressureEquilibration, MixtureCompressibilityWeighsByVolumeFraction) {
  const std::vector<double> bulk{0.1 * 2.4, 0.3 * 1000.0}, temperature{293.15, 288.15};
  const CellEquilibrium cell = equilibrate_pressure(kAirWater, bulk, temperature, 0.4);
  const double kappa = mixture_compressibility(cell.volume_fraction, cell.compressibility);
  const double expected = (cell.volume_fraction[0] / cell.pressure +
                           cell.volume_fraction[1] / (cell.density[1] * kWater.stiffness())) /
                          0.4;
  EXPECT_NEAR(kappa, expected, 1e-14 * expected);
  // The air dominates: kappa ~ phi_a / (n P).
  EXPECT_NEAR(kappa * 0.4 * cell.pressure / cell.volume_fraction[0], 1.0, 1e-3);
}

TEST(PressureEquilibration, NonConvergenceReportsTheIterations) {
  const std::vector<double> bulk{0.1 * 2.4, 0.3 * 1000.0}, temperature{293.15, 288.15};
  const auto error = equilibration_error([&] {
    equilibrate_pressure(kAirWater, bulk, temperature, 0.4, 1e10,
                         {.tolerance = 1e-12, .max_iterations = 1});
  });
  EXPECT_EQ(error.iterations(), 1);
  EXPECT_TRUE(mentions(error, "did not converge in 1 iteration:"));
  EXPECT_TRUE(std::isfinite(error.residual()));
  EXPECT_FALSE(error.cell().has_value());
  EXPECT_EQ(error.code(), cosim::ExitCode::numerical_failure);
}

TEST(PressureEquilibration, PoresThatCannotBeFilledAreRefused) {
  // Water stretched to half its density with the air absent: only a tension
  // fills the pores, and the air has no state below P = 0.
  const std::vector<double> bulk{0.0, 0.5 * 999.8}, temperature{283.15, 283.15};
  const auto error =
      equilibration_error([&] { equilibrate_pressure(kAirWater, bulk, temperature, 1.0); });
  EXPECT_EQ(error.iterations(), 0);
  EXPECT_EQ(error.pressure(), 0.0);
  EXPECT_NEAR(error.residual(), -0.5, 1e-3);
  EXPECT_TRUE(mentions(error, "material 0 (ideal_gas) (absent)"));
}

TEST(PressureEquilibration, BadInputIsRefused) {
  const std::vector<double> bulk{0.1, 300.0}, temperature{293.15, 288.15};
  for (const double n : {0.0, -0.1, 1.0 + 1e-12, std::nan("")}) {
    const auto error =
        equilibration_error([&] { equilibrate_pressure(kAirWater, bulk, temperature, n); });
    EXPECT_TRUE(mentions(error, "porosity")) << n;
    EXPECT_EQ(error.iterations(), 0);
  }
  auto error = equilibration_error([&] {
    equilibrate_pressure(kAirWater, std::vector<double>{0.1, -1.0}, temperature, 0.4);
  });
  EXPECT_TRUE(mentions(error, "material 1 (linear_water): bulk density -1"));
  error = equilibration_error([&] {
    equilibrate_pressure(kAirWater, std::vector<double>{0.0, 0.0}, temperature, 0.4);
  });
  EXPECT_TRUE(mentions(error, "no fluid material has a positive bulk density"));
  error = equilibration_error([&] {
    equilibrate_pressure(kAirWater, bulk, std::vector<double>{0.0, 288.0}, 0.4);
  });
  EXPECT_TRUE(mentions(error, "material 0 (ideal_gas): temperature 0 K"));
  EXPECT_THROW(equilibrate_pressure(kAirWater, std::vector<double>{1.0}, temperature, 0.4),
               std::invalid_argument);
  EXPECT_THROW(
      equilibrate_pressure(kAirWater, bulk, temperature, 0.4, one_atmosphere, {.tolerance = 0.0}),
      std::invalid_argument);
}

TEST(PressureEquilibration, BatchedMatchesCellByCell) {
  const std::vector<double> n{1.0, 0.4, 0.55, 0.3};
  const std::vector<double> air_bulk{1.2, 0.24, 0.0, 1e-6};
  const std::vector<double> water_bulk{0.0, 300.0, 0.55 * 1000.5, 0.299 * 1000.0};
  const std::vector<double> air_T{300.0, 293.15, 280.0, 285.0};
  const std::vector<double> water_T{300.0, 288.15, 280.0, 285.0};
  const std::vector<MaterialCells> materials{{&kAir, air_bulk, air_T},
                                             {&kWater, water_bulk, water_T}};
  const EquilibratedCells cells = equilibrate_pressure(materials, n, std::vector<double>{});
  ASSERT_EQ(cells.pressure.size(), 4u);
  int most = 0;
  for (std::size_t c = 0; c < n.size(); ++c) {
    const std::vector<double> bulk{air_bulk[c], water_bulk[c]}, temperature{air_T[c], water_T[c]};
    const CellEquilibrium one = equilibrate_pressure(kAirWater, bulk, temperature, n[c]);
    EXPECT_EQ(cells.pressure[c], one.pressure) << c;
    for (std::size_t f = 0; f < 2; ++f) {
      EXPECT_EQ(cells.density[f][c], one.density[f]);
      EXPECT_EQ(cells.volume_fraction[f][c], one.volume_fraction[f]);
      EXPECT_EQ(cells.compressibility[f][c], one.compressibility[f]);
    }
    const double filled = cells.volume_fraction[0][c] + cells.volume_fraction[1][c] - n[c];
    EXPECT_LE(std::abs(filled), 1e-12 * n[c]);
    most = std::max(most, one.iterations);
    std::cout << "    cell " << c << ": P " << cells.pressure[c] << " Pa, sum phi - n " << filled
              << '\n';
  }
  EXPECT_EQ(cells.most_iterations, most);

  // The previous pressures as guesses: converged cells need no iteration.
  const EquilibratedCells again = equilibrate_pressure(materials, n, cells.pressure);
  EXPECT_EQ(again.most_iterations, 0);
}

// The batched solve over many cells (all evaluated together while most
// iterate, the last ones one by one; cells with an absent material through
// the one-cell path) gives each cell the one-cell result to the bit.
TEST(PressureEquilibration, BatchedMatchesCellByCellOnManyRandomCells) {
  std::mt19937 rng(7u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t cells = 2000;
  std::vector<double> n(cells), air_bulk(cells), water_bulk(cells), air_T(cells), water_T(cells),
      guess(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    n[c] = c % 3 == 0 ? 1.0 : 0.2 + 0.8 * u(rng);
    const double p = 1e5 * (0.5 + u(rng));
    const bool no_air = c % 97 == 0;
    const double water_fraction =
        no_air ? 1.0 : (c % 5 == 0 ? 1e-6 : (c % 5 == 1 ? 1.0 - 1e-6 : u(rng)));
    air_T[c] = 250.0 + 100.0 * u(rng);
    water_T[c] = 275.0 + 60.0 * u(rng);
    air_bulk[c] = (1.0 - water_fraction) * n[c] * kAir.density(p, air_T[c]);
    water_bulk[c] = water_fraction * n[c] * kWater.density(p, water_T[c]);
    // Guesses from close (most cells) to far off (a few need many steps).
    guess[c] = c % 50 == 0 ? 1e7 : p * (1.0 + 0.01 * (u(rng) - 0.5));
  }
  const std::vector<MaterialCells> materials{{&kAir, air_bulk, air_T},
                                             {&kWater, water_bulk, water_T}};
  EquilibratedCells batched;
  equilibrate_pressure(materials, n, guess, {}, batched);
  int most = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::vector<double> bulk{air_bulk[c], water_bulk[c]}, temperature{air_T[c], water_T[c]};
    const CellEquilibrium one = equilibrate_pressure(kAirWater, bulk, temperature, n[c], guess[c]);
    ASSERT_EQ(batched.pressure[c], one.pressure) << c;
    for (std::size_t f = 0; f < 2; ++f) {
      ASSERT_EQ(batched.density[f][c], one.density[f]) << c;
      ASSERT_EQ(batched.volume_fraction[f][c], one.volume_fraction[f]) << c;
      ASSERT_EQ(batched.compressibility[f][c], one.compressibility[f]) << c;
    }
    most = std::max(most, one.iterations);
  }
  EXPECT_EQ(batched.most_iterations, most);
  std::cout << "    " << cells << " cells, most iterations " << most << '\n';
}

TEST(PressureEquilibration, BatchedErrorNamesTheCell) {
  const std::vector<double> n{0.4, 0.4, 0.4};
  const std::vector<double> air_bulk{0.24, 0.24, 0.24}, water_bulk{300.0, 300.0, 300.0};
  const std::vector<double> air_T{293.0, 293.0, -5.0}, water_T{288.0, 288.0, 288.0};
  const std::vector<MaterialCells> materials{{&kAir, air_bulk, air_T},
                                             {&kWater, water_bulk, water_T}};
  const auto error =
      equilibration_error([&] { equilibrate_pressure(materials, n, std::vector<double>{}); });
  ASSERT_TRUE(error.cell().has_value());
  EXPECT_EQ(*error.cell(), 2u);
  EXPECT_TRUE(
      mentions(error, "cell 2: pressure equilibration: material 0 (ideal_gas): temperature -5 K"));

  const auto slow = equilibration_error([&] {
    const std::vector<double> warm{293.0, 293.0, 293.0};
    const std::vector<MaterialCells> good{{&kAir, air_bulk, warm}, {&kWater, water_bulk, water_T}};
    const EquilibratedCells converged = equilibrate_pressure(good, n, std::vector<double>{});
    std::vector<double> guess = converged.pressure;
    guess[2] = 1e12;
    equilibrate_pressure(good, n, guess, {.max_iterations = 3});
  });
  EXPECT_EQ(*slow.cell(), 2u);
  EXPECT_EQ(slow.iterations(), 3);
  EXPECT_TRUE(mentions(slow, "cell 2: pressure equilibration did not converge in 3 iterations"));
  EXPECT_THROW(equilibrate_pressure(materials, std::vector<double>{0.4}, std::vector<double>{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace ice::testing

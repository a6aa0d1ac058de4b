#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "eos_test_support.hpp"

namespace ice::testing {
namespace {

struct State {
  double density;
  double temperature;
};

// rho -> P -> rho and P -> rho -> P at fixed T, to round-off: the P error
// is bounded by eps (|P| + rho dP/drho), the conditioning of P(rho).
void expect_round_trips(const EquationOfState& eos, const std::vector<State>& states) {
  double worst_density = 0.0;
  double worst_pressure = 0.0;
  for (const auto& [rho, T] : states) {
    const double p = eos.pressure(rho, T);
    const double density_error = std::abs(eos.density(p, T) - rho) / rho;
    EXPECT_LE(density_error, 4 * eps) << eos.type() << " rho " << rho << " T " << T;
    const double pressure_scale = std::abs(p) + rho * eos.dpressure_ddensity(rho, T);
    const double pressure_error = std::abs(eos.pressure(eos.density(p, T), T) - p) / pressure_scale;
    EXPECT_LE(pressure_error, 4 * eps) << eos.type() << " P " << p << " T " << T;
    worst_density = std::max(worst_density, density_error);
    worst_pressure = std::max(worst_pressure, pressure_error);
  }
  std::cout << "    " << eos.type() << ": round trip rel. error rho " << worst_density << ", P "
            << worst_pressure << " (of |P| + rho c^2); tolerance " << 4 * eps << '\n';
}

// (dP/drho)_T, the compressibility and the thermal expansivity against
// central differences of pressure() and density().
void expect_derivatives_match_differences(const EquationOfState& eos, const State& state) {
  const auto [rho, T] = state;
  const double h = 1e-5 * rho;
  const double dp_drho = (eos.pressure(rho + h, T) - eos.pressure(rho - h, T)) / (2 * h);
  const double dp_error = std::abs(eos.dpressure_ddensity(rho, T) - dp_drho) / dp_drho;
  EXPECT_LE(dp_error, 1e-8) << eos.type();

  const double p = eos.pressure(rho, T);
  const double dp = 1e-5 * rho * eos.dpressure_ddensity(rho, T);
  const double kappa = (eos.density(p + dp, T) - eos.density(p - dp, T)) / (2 * dp) / rho;
  const double kappa_error = std::abs(eos.compressibility(rho, T) - kappa) / kappa;
  EXPECT_LE(kappa_error, 1e-8) << eos.type();
  EXPECT_DOUBLE_EQ(eos.compressibility(rho, T),
                   1.0 / (rho * std::pow(eos.isothermal_sound_speed(rho, T), 2)));

  const double dT = 1e-3;
  const double alpha = -(eos.density(p, T + dT) - eos.density(p, T - dT)) / (2 * dT) / rho;
  const double alpha_error = std::abs(eos.thermal_expansivity(rho, T) - alpha) / alpha;
  EXPECT_LE(alpha_error, 1e-6) << eos.type();
  std::cout << "    " << eos.type() << ": dP/drho " << eos.dpressure_ddensity(rho, T)
            << " rel. err " << dp_error << " (tol 1e-8); kappa " << eos.compressibility(rho, T)
            << " rel. err " << kappa_error << " (tol 1e-8); alpha "
            << eos.thermal_expansivity(rho, T) << " rel. err " << alpha_error << " (tol 1e-6)\n";
}

TEST(IdealGas, PressureAndDensityRoundTrip) {
  expect_round_trips(air(), {{1.177, 278.15}, {1e-3, 200.0}, {50.0, 900.0}, {0.3, 1500.0}});
}

TEST(IdealGas, DerivativesMatchFiniteDifferences) {
  expect_derivatives_match_differences(air(), {1.177, 278.15});
  expect_derivatives_match_differences(air(), {20.0, 600.0});
}

TEST(IdealGas, IsThePerfectGasLaw) {
  const IdealGas gas = air();
  // Tran et al., MPMICE, eq. 34; isothermal c^2 = R T, kappa = 1/P.
  EXPECT_DOUBLE_EQ(gas.pressure(1.2, 300.0), 1.2 * 287.05 * 300.0);
  EXPECT_DOUBLE_EQ(gas.compressibility(1.2, 300.0), 1.0 / gas.pressure(1.2, 300.0));
  EXPECT_DOUBLE_EQ(gas.isothermal_sound_speed(1.2, 300.0), std::sqrt(287.05 * 300.0));
  EXPECT_EQ(gas.minimum_pressure(300.0), 0.0);
  EXPECT_DOUBLE_EQ(gas.specific_heat(), 717.625);
  EXPECT_DOUBLE_EQ(gas.specific_internal_energy(300.0), 717.625 * 300.0);
}

TEST(LinearWater, PressureAndDensityRoundTrip) {
  expect_round_trips(water(),
                     {{999.8, 283.15}, {1000.5, 278.15}, {998.0, 293.15}, {1010.0, 350.0}});
}

TEST(LinearWater, DerivativesMatchFiniteDifferences) {
  expect_derivatives_match_differences(water(), {999.8, 283.15});
  expect_derivatives_match_differences(water(), {1003.0, 300.0});
}

TEST(LinearWater, CoefficientsOfEquation35) {
  const LinearWater w = water();
  // K_f = K_bulk / rho_ref [m2/s2]; alpha_f = rho_ref beta [kg/(m3 K)].
  EXPECT_DOUBLE_EQ(w.stiffness(), 2.15e9 / 999.8);
  EXPECT_DOUBLE_EQ(w.thermal_density_slope(), 999.8 * 2.1e-4);
  const double c = w.isothermal_sound_speed(999.8, 283.15);
  EXPECT_NEAR(c, 1466.4, 0.1);
  EXPECT_DOUBLE_EQ(w.pressure(999.8, 283.15), 101325.0);
  // At rho_ref the compressibility is 1 / K_bulk.
  EXPECT_NEAR(w.compressibility(999.8, 283.15) * 2.15e9, 1.0, 4 * eps);
  // 1 MPa more compresses water by 1/K_bulk ~ 4.7e-4.
  const double squeezed = w.density(101325.0 + 1e6, 283.15);
  EXPECT_NEAR(squeezed / 999.8 - 1.0, 1e6 / 2.15e9, 1e-12);
  // Warming from 10 to 20 degC at 1 atm: -2.1 kg/m3 (real water: -1.5).
  const double warm = w.density(101325.0, 293.15);
  EXPECT_NEAR(warm - 999.8, -999.8 * 2.1e-4 * 10.0, 1e-9);
  EXPECT_NEAR(w.density(w.minimum_pressure(293.15), 293.15), 0.0, 1e-6);
  std::cout << "    c_T " << c << " m/s, rho(20 degC, 1 atm) " << warm << " kg/m3, P_min(20 degC) "
            << w.minimum_pressure(293.15) << " Pa\n";
}

TEST(EquationOfState, ConstructorsRefuseNonPhysicalParameters) {
  EXPECT_THROW(IdealGas(0.0, 717.0), std::invalid_argument);
  EXPECT_THROW(IdealGas(287.0, -1.0), std::invalid_argument);
  LinearWaterParameters p;
  p.bulk_modulus = -2e9;
  EXPECT_THROW(LinearWater{p}, std::invalid_argument);
  p = {};
  p.reference_density = 0.0;
  EXPECT_THROW(LinearWater{p}, std::invalid_argument);
  p = {};
  p.thermal_expansion = -1e-4;
  EXPECT_THROW(LinearWater{p}, std::invalid_argument);
}

}  // namespace
}  // namespace ice::testing

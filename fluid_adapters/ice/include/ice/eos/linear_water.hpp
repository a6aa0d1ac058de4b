#pragma once

#include <memory>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "ice/eos/equation_of_state.hpp"

namespace ice {

// The physical constants of the linear water law, as a user gives them.
struct LinearWaterParameters {
  double bulk_modulus = 2.0e9;            // K_bulk = rho dP/drho [Pa]
  double reference_density = 999.8;       // rho_ref [kg/m3]
  double reference_pressure = 101325.0;   // P_ref [Pa]
  double reference_temperature = 283.15;  // T_ref [K] (10 degC)
  double thermal_expansion = 2.1e-4;      // beta = -(1/rho)(drho/dT)_P [1/K]
  double specific_heat = 4182.0;          // c_v [J/(kg K)]
};

// Linear water, Tran et al., MPMICE, eq. 35:
//
//   P = P_ref + K_f (rho - rho_ref + alpha_f (T - T_ref)).
//
// The bracket is a density, so K_f is dP/drho [m2/s2], a squared sound speed:
// K_f = K_bulk / rho_ref (the paper's "bulk modulus 2 GPa" gives
// K_f = 2.0e6 m2/s2, c = 1414 m/s; its Table 1's 2.15e9 Pa gives 1466 m/s),
// and alpha_f [kg/(m3 K)] is the density drop per kelvin,
// alpha_f = rho_ref beta. The paper's alpha_f = 0.18 is physical only read in
// these units (beta = 1.8e-4 1/K); read as a volumetric coefficient, 0.18 1/K
// is ~1000 times water's. The default beta = 2.1e-4 1/K is water's at 20 degC.
class LinearWater final : public EquationOfState {
 public:
  static constexpr std::string_view name = "linear_water";
  static cosim::config::Schema schema();
  static std::unique_ptr<EquationOfState> make(const cosim::config::Node& parameters);

  // Throws std::invalid_argument unless bulk_modulus, reference_density,
  // reference_temperature and specific_heat are positive, thermal_expansion
  // non-negative and all finite.
  explicit LinearWater(const LinearWaterParameters& parameters);

  std::string_view type() const override { return name; }
  const LinearWaterParameters& parameters() const { return parameters_; }
  double stiffness() const { return stiffness_; }                          // K_f [m2/s2]
  double thermal_density_slope() const { return thermal_density_slope_; }  // alpha_f [kg/(m3 K)]

  // Tran et al., MPMICE, eq. 35 (inline: the pressure equilibration calls
  // these per cell and Newton iteration).
  double pressure(double density, double temperature) const override {
    return parameters_.reference_pressure +
           stiffness_ *
               (density - parameters_.reference_density +
                thermal_density_slope_ * (temperature - parameters_.reference_temperature));
  }
  double density(double pressure, double temperature) const override {
    return density_at_reference_pressure(temperature) +
           (pressure - parameters_.reference_pressure) / stiffness_;
  }
  double minimum_pressure(double temperature) const override {
    return parameters_.reference_pressure - stiffness_ * density_at_reference_pressure(temperature);
  }
  double dpressure_ddensity(double /*density*/, double /*temperature*/) const override {
    return stiffness_;
  }
  double thermal_expansivity(double density, double /*temperature*/) const override {
    return thermal_density_slope_ / density;
  }

 private:
  // rho at P = P_ref and temperature T.
  double density_at_reference_pressure(double temperature) const {
    return parameters_.reference_density -
           thermal_density_slope_ * (temperature - parameters_.reference_temperature);
  }

  LinearWaterParameters parameters_;
  double stiffness_;
  double thermal_density_slope_;
};

}  // namespace ice

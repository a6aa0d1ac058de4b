#pragma once

#include <memory>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "ice/eos/equation_of_state.hpp"

namespace ice {

// Perfect gas, P = rho R T (Tran et al., MPMICE, eq. 34), with R the specific
// gas constant [J/(kg K)] (287.05 for dry air) and a constant c_v.
class IdealGas final : public EquationOfState {
 public:
  static constexpr std::string_view name = "ideal_gas";
  static cosim::config::Schema schema();
  // Needs gas_constant and one of specific_heat or heat_capacity_ratio
  // (gamma > 1, c_v = R / (gamma - 1)).
  static std::unique_ptr<EquationOfState> make(const cosim::config::Node& parameters);

  // Throws std::invalid_argument unless both are positive and finite.
  IdealGas(double gas_constant, double specific_heat);

  std::string_view type() const override { return name; }
  double gas_constant() const { return gas_constant_; }

  double pressure(double density, double temperature) const override {
    return density * gas_constant_ * temperature;
  }
  double density(double pressure, double temperature) const override {
    return pressure / (gas_constant_ * temperature);
  }
  double minimum_pressure(double /*temperature*/) const override { return 0.0; }
  double dpressure_ddensity(double /*density*/, double temperature) const override {
    return gas_constant_ * temperature;
  }
  double thermal_expansivity(double /*density*/, double temperature) const override {
    return 1.0 / temperature;
  }

 private:
  double gas_constant_;
};

}  // namespace ice

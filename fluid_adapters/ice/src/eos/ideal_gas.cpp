#include "ice/eos/ideal_gas.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace ice {

using cosim::config::Node;
using cosim::config::Schema;

IdealGas::IdealGas(double gas_constant, double specific_heat)
    : EquationOfState(specific_heat), gas_constant_(gas_constant) {
  if (!(gas_constant > 0.0 && std::isfinite(gas_constant))) {
    throw std::invalid_argument(
        fmt::format("ideal gas: gas constant must be > 0 (got {})", gas_constant));
  }
  if (!(specific_heat > 0.0 && std::isfinite(specific_heat))) {
    throw std::invalid_argument(
        fmt::format("ideal gas: specific heat must be > 0 (got {})", specific_heat));
  }
}

Schema IdealGas::schema() {
  Schema schema = Schema::object("Perfect gas P = rho R T (Tran et al., MPMICE, eq. 34).");
  schema.required("type", Schema::one_of({std::string(name)}), "The equation of state.")
      .required("gas_constant", Schema::number().positive().unit("J/(kg K)"),
                "Specific gas constant R (287.05 for dry air).")
      .optional("specific_heat", Schema::number().positive().unit("J/(kg K)"),
                "Specific heat at constant volume c_v; give this or heat_capacity_ratio.")
      .optional("heat_capacity_ratio", Schema::number(),
                "gamma = c_p / c_v > 1 (1.4 for air), giving c_v = R / (gamma - 1); "
                "give this or specific_heat.");
  return schema;
}

std::unique_ptr<EquationOfState> IdealGas::make(const Node& parameters) {
  const double gas_constant = parameters["gas_constant"].as<double>();
  const auto specific_heat = parameters.find("specific_heat");
  const auto ratio = parameters.find("heat_capacity_ratio");
  if (specific_heat && ratio) {
    ratio->fail_at_key("give specific_heat or heat_capacity_ratio, not both");
  }
  if (specific_heat) return std::make_unique<IdealGas>(gas_constant, specific_heat->as<double>());
  if (!ratio) parameters.fail("ideal_gas needs specific_heat or heat_capacity_ratio");
  const double gamma = ratio->as<double>();
  const double specific_heat_from_ratio = gas_constant / (gamma - 1.0);
  if (!(gamma > 1.0 && std::isfinite(specific_heat_from_ratio))) {
    ratio->fail(fmt::format("heat_capacity_ratio must be > 1 (got {})", gamma));
  }
  return std::make_unique<IdealGas>(gas_constant, specific_heat_from_ratio);
}

}  // namespace ice

#include "ice/eos/linear_water.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ice {

using cosim::config::Node;
using cosim::config::Schema;

namespace {

void require(bool ok, std::string_view what, double value) {
  if (!ok) throw std::invalid_argument(fmt::format("linear water: {} (got {})", what, value));
}

}  // namespace

LinearWater::LinearWater(const LinearWaterParameters& p)
    : EquationOfState(p.specific_heat),
      parameters_(p),
      stiffness_(p.bulk_modulus / p.reference_density),
      thermal_density_slope_(p.reference_density * p.thermal_expansion) {
  require(p.bulk_modulus > 0.0 && std::isfinite(p.bulk_modulus), "bulk modulus must be > 0",
          p.bulk_modulus);
  require(p.reference_density > 0.0 && std::isfinite(p.reference_density),
          "reference density must be > 0", p.reference_density);
  require(std::isfinite(p.reference_pressure), "reference pressure must be finite",
          p.reference_pressure);
  require(p.reference_temperature > 0.0 && std::isfinite(p.reference_temperature),
          "reference temperature must be > 0 K", p.reference_temperature);
  require(p.thermal_expansion >= 0.0 && std::isfinite(p.thermal_expansion),
          "thermal expansion must be >= 0", p.thermal_expansion);
  require(p.specific_heat > 0.0 && std::isfinite(p.specific_heat), "specific heat must be > 0",
          p.specific_heat);
}

Schema LinearWater::schema() {
  const LinearWaterParameters defaults;
  Schema schema = Schema::object(
      "Linear water P = P_ref + (K / rho_ref) (rho - rho_ref + rho_ref beta (T - T_ref)) "
      "(Tran et al., MPMICE, eq. 35).");
  schema.required("type", Schema::one_of({std::string(name)}), "The equation of state.")
      .required("bulk_modulus", Schema::number().positive().unit("Pa"),
                "Bulk modulus K = rho dP/drho (2.0e9 to 2.2e9 for water).")
      .required("reference_density", Schema::number().positive().unit("kg/m3"),
                "Density rho_ref at P_ref and T_ref (999.8 for fresh water at 10 degC).")
      .optional(
          "reference_pressure",
          Schema::number().unit("Pa").default_value(fmt::format("{}", defaults.reference_pressure)),
          "Reference pressure P_ref.")
      .optional("reference_temperature",
                Schema::number().positive().unit("K").default_value(
                    fmt::format("{}", defaults.reference_temperature)),
                "Reference temperature T_ref.")
      .optional("thermal_expansion",
                Schema::number().non_negative().unit("1/K").default_value(
                    fmt::format("{}", defaults.thermal_expansion)),
                "Volumetric thermal expansion beta = -(1/rho) drho/dT (water at 20 degC); "
                "eq. 35's alpha is rho_ref beta.")
      .optional("specific_heat",
                Schema::number()
                    .positive()
                    .unit("J/(kg K)")
                    .default_value(fmt::format("{}", defaults.specific_heat)),
                "Specific heat at constant volume c_v.");
  return schema;
}

std::unique_ptr<EquationOfState> LinearWater::make(const Node& node) {
  LinearWaterParameters p;
  p.bulk_modulus = node["bulk_modulus"].as<double>();
  p.reference_density = node["reference_density"].as<double>();
  p.reference_pressure = node.get("reference_pressure", p.reference_pressure);
  p.reference_temperature = node.get("reference_temperature", p.reference_temperature);
  p.thermal_expansion = node.get("thermal_expansion", p.thermal_expansion);
  p.specific_heat = node.get("specific_heat", p.specific_heat);
  return std::make_unique<LinearWater>(p);
}

}  // namespace ice

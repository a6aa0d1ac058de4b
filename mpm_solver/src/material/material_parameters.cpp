#include "mpm/material/material_parameters.hpp"

#include <fmt/format.h>

#include <numbers>

namespace mpm::material_parameters {

using cosim::config::Node;
using cosim::config::Schema;

Schema base_schema(const std::string& type, std::string doc, bool hypoelastic) {
  Schema schema = Schema::object(std::move(doc));
  schema.required("type", Schema::one_of({type}), "The constitutive model.")
      .required(
          "density", Schema::number().positive().unit("kg/m3"),
          "Density of the material: the grain density of a porous body, else the bulk density.");
  add_thermal_keys(schema);
  if (hypoelastic) {
    schema.optional(
        "objective_rate", Schema::one_of({"jaumann", "polar_rotation"}).default_value("jaumann"),
        "How the stress is kept objective under rotation: the Jaumann rate (Zheng et al., eq. 5) "
        "or the polar rotation of F (Tran et al., MPMICE, eqs. 11-14).");
  }
  return schema;
}

Schema& add_elastic_keys(Schema& schema) {
  return schema
      .required("youngs_modulus", Schema::number().positive().unit("Pa"), "Young's modulus E.")
      .required("poisson_ratio", Schema::number(),
                "Poisson's ratio nu in [-1, 0.5); 0.5 (incompressible) is refused.");
}

Schema& add_thermal_keys(Schema& schema, const std::string& whose) {
  return schema
      .optional("specific_heat", Schema::number().positive().unit("J/(kg K)"),
                whose +
                    "Specific heat c (of the grains for a porous body). A body with a specific "
                    "heat is thermal: its temperature conducts and exchanges heat.")
      .optional("thermal_conductivity",
                Schema::number().non_negative().unit("W/(m K)").default_note("0"),
                whose +
                    "Thermal conductivity k (of the grains: a porous skeleton conducts with "
                    "(1 - n) k); needs specific_heat.");
}

namespace {

double positive(const Node& node, std::string_view key) {
  const Node value = node[key];
  const double x = value.as<double>();
  if (!(x > 0.0)) value.fail(fmt::format("{} must be > 0 (got {})", key, x));
  return x;
}

}  // namespace

CommonProperties read_common_properties(const Node& node) {
  return {.density = positive(node, "density"), .thermal = read_thermal_properties(node)};
}

std::optional<ThermalProperties> read_thermal_properties(const Node& node) {
  const auto specific_heat = node.find("specific_heat");
  const auto conductivity = node.find("thermal_conductivity");
  if (!specific_heat) {
    if (conductivity)
      conductivity->fail_at_key(
          "thermal_conductivity needs specific_heat (only a body that stores heat conducts it)");
    return std::nullopt;
  }
  return ThermalProperties{.specific_heat = positive(node, "specific_heat"),
                           .conductivity = conductivity ? conductivity->as<double>() : 0.0};
}

ObjectiveRate read_objective_rate(const Node& node) {
  return node.get<std::string>("objective_rate") == "polar_rotation" ? ObjectiveRate::polar_rotation
                                                                     : ObjectiveRate::jaumann;
}

ElasticConstants read_elastic_constants(const Node& node) {
  const double youngs = positive(node, "youngs_modulus");
  const Node poisson = node["poisson_ratio"];
  const double nu = poisson.as<double>();
  if (!(nu < 0.5)) poisson.fail(fmt::format("poisson_ratio must be < 0.5 (got {})", nu));
  if (!(nu >= -1.0)) poisson.fail(fmt::format("poisson_ratio must be >= -1 (got {})", nu));
  return ElasticConstants::from_youngs_poisson(youngs, nu);
}

double read_angle(const Node& node, std::string_view key, double fallback_degrees,
                  double below_degrees) {
  double degrees = fallback_degrees;
  if (const auto value = node.find(key)) {
    degrees = value->as<double>();
    if (!(degrees >= 0.0 && degrees < below_degrees)) {
      value->fail(
          fmt::format("{} must be in [0, {}) degrees (got {})", key, below_degrees, degrees));
    }
  }
  return degrees * std::numbers::pi / 180.0;
}

}  // namespace mpm::material_parameters

#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/elastic_constants.hpp"
#include "mpm/material/material.hpp"

// Keys every model shares, declared once for the schemas and read once for
// the makers: `type`, `density`, the thermal properties, `objective_rate`,
// the elastic constants and angles in degrees.
namespace mpm::material_parameters {

// A mapping with `type: <type>`, `density` and the thermal keys; with
// `objective_rate` too unless the model is hyperelastic.
cosim::config::Schema base_schema(const std::string& type, std::string doc,
                                  bool hypoelastic = true);

// Adds `youngs_modulus` and `poisson_ratio`.
cosim::config::Schema& add_elastic_keys(cosim::config::Schema& schema);

// Adds the optional `specific_heat` and `thermal_conductivity` (also the keys
// of a rigid body's own thermal properties); `whose` starts their docs.
cosim::config::Schema& add_thermal_keys(cosim::config::Schema& schema,
                                        const std::string& whose = "");

// `density` > 0, refused at its key otherwise; and the thermal properties.
CommonProperties read_common_properties(const cosim::config::Node& node);

// None without `specific_heat`; `thermal_conductivity` (default 0) alone is
// refused at its key.
std::optional<ThermalProperties> read_thermal_properties(const cosim::config::Node& node);

ObjectiveRate read_objective_rate(const cosim::config::Node& node);

// K and G from `youngs_modulus` > 0 and `poisson_ratio` in [-1, 0.5).
ElasticConstants read_elastic_constants(const cosim::config::Node& node);

// The angle at `key` in degrees, checked to lie in [0, `below_degrees`), in
// radians; `fallback_degrees` when the key is absent.
double read_angle(const cosim::config::Node& node, std::string_view key, double fallback_degrees,
                  double below_degrees = 90.0);

}  // namespace mpm::material_parameters

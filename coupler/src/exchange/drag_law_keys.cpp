#include "exchange/drag_law_keys.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "cosim/error.hpp"

namespace cosim::exchange::drag_law_keys {

using config::Schema;

namespace {

Schema positive_or_per_cell(const char* unit) {
  return Schema::any_of({Schema::number().positive().unit(unit), Schema::one_of({"field"})});
}

}  // namespace

Schema base_schema(std::string_view law, std::string doc) {
  Schema schema = Schema::object(std::move(doc));
  schema.required("law", Schema::one_of({std::string(law)}), "The drag law.");
  return schema;
}

void add_fluid_viscosity(Schema& schema) {
  schema.required("fluid_viscosity", Schema::number().positive().unit("Pa s"),
                  "Dynamic viscosity mu_f of the pore fluid.");
}

void add_grain_size(Schema& schema) {
  schema.required("grain_size", positive_or_per_cell("m"),
                  "Grain size D_p; `field`: per cell, from the solid's grain_size field.");
}

void add_bed_length_scale(Schema& schema) {
  schema
      .optional("grain_size", positive_or_per_cell("m"),
                "Grain size D_p (D50); `field`: per cell, from the solid's grain_size field. "
                "Give exactly one of grain_size and permeability.")
      .optional("permeability", positive_or_per_cell("m^2"),
                "Intrinsic permeability kappa; `field`: per cell, from the solid's "
                "permeability field.");
}

std::optional<double> value_or_per_cell(const config::Node& value) {
  if (value.is_scalar() && value.as<std::string>() == "field") return std::nullopt;
  return value.as<double>();
}

BedLengthScale read_bed_length_scale(const config::Node& node) {
  const auto grain_size = node.find("grain_size");
  const auto permeability = node.find("permeability");
  if (grain_size.has_value() == permeability.has_value()) {
    const std::string what =
        "give exactly one of 'grain_size' [m] and 'permeability' [m^2] (a number or 'field')";
    if (permeability) permeability->fail(what);
    throw InputError(node.location(), node.key_path() + ".grain_size", what);
  }
  if (grain_size) return {true, value_or_per_cell(*grain_size)};
  return {false, value_or_per_cell(*permeability)};
}

double checked_cell_value(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0) {
    throw NumericalError(fmt::format("per-cell {} must be finite and > 0, got {}", what, value));
  }
  return value;
}

}  // namespace cosim::exchange::drag_law_keys

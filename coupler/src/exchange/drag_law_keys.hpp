#pragma once

#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"

// The keys the drag laws share: their schemas' pieces and the readers of the
// values a law may take per cell.
namespace cosim::exchange::drag_law_keys {

// A law's mapping: `law: <law>` and the keys the caller adds.
config::Schema base_schema(std::string_view law, std::string doc);

// fluid_viscosity: mu_f [Pa s], required.
void add_fluid_viscosity(config::Schema& schema);

// grain_size [m] or `field`, required.
void add_grain_size(config::Schema& schema);

// Exactly one of grain_size [m] and permeability [m^2], each a number or
// `field` (read per cell); which one is the maker's check.
void add_bed_length_scale(config::Schema& schema);

// A number, or nullopt where the key holds `field`.
std::optional<double> value_or_per_cell(const config::Node& value);

// The length scale of a permeable bed, read after add_bed_length_scale's keys.
struct BedLengthScale {
  bool from_grain_size = true;
  std::optional<double> value;  // nullopt: per cell
};
BedLengthScale read_bed_length_scale(const config::Node& node);

// A per-cell length scale the law reads must be finite and > 0.
double checked_cell_value(double value, const char* what);

}  // namespace cosim::exchange::drag_law_keys

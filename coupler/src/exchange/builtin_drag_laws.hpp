#pragma once

#include <memory>
#include <optional>
#include <string>

#include "exchange/drag_law.hpp"
#include "exchange/drag_parameters.hpp"

// Factories of the built-in drag laws, each defined next to its law.
namespace cosim::exchange::detail {

std::unique_ptr<DragLaw> make_kozeny_carman(DragParameters& parameters);
std::unique_ptr<DragLaw> make_forchheimer(DragParameters& parameters);
std::unique_ptr<DragLaw> make_beetstra(DragParameters& parameters);
std::unique_ptr<DragLaw> make_constant_drag(DragParameters& parameters);

// The length scale of a permeable bed: exactly one of `grain_size` [m] or
// `permeability` [m^2], each a number or `field` (nullopt value).
struct BedLengthScale {
  bool from_grain_size = true;
  std::optional<double> value;
};
BedLengthScale read_bed_length_scale(DragParameters& parameters);

// A per-cell length scale the law reads must be finite and > 0.
double checked_cell_value(double value, const char* what);

}  // namespace cosim::exchange::detail

#include "swe/two_phase/solid_layer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cosim/error.hpp"

namespace swe {

SolidLayer empty_solid_layer(std::size_t cells, double density) {
  SolidLayer layer;
  layer.depth.assign(cells, 0.0);
  layer.velocity_x.assign(cells, 0.0);
  layer.velocity_y.assign(cells, 0.0);
  layer.density.assign(cells, density);
  layer.structured_share.assign(cells, 0.0);
  return layer;
}

namespace {

enum class Range { any, non_negative, positive, fraction };

void check_array(const std::vector<double>& values, const char* quantity, const char* unit,
                 std::size_t cells, bool may_be_empty, Range range) {
  if (values.empty() && may_be_empty) return;
  if (values.size() != cells)
    throw cosim::InputError(
        fmt::format("solid layer: {} has {} values for {} cells", quantity, values.size(), cells));
  for (std::size_t c = 0; c < cells; ++c) {
    const double v = values[c];
    const bool ok =
        std::isfinite(v) && (range == Range::any || (range == Range::non_negative && v >= 0.0) ||
                             (range == Range::positive && v > 0.0) ||
                             (range == Range::fraction && v >= 0.0 && v <= 1.0));
    if (!ok) {
      const char* expected = range == Range::non_negative ? "finite and >= 0"
                             : range == Range::positive   ? "finite and > 0"
                             : range == Range::fraction   ? "in [0, 1]"
                                                          : "finite";
      throw cosim::InputError(fmt::format("solid layer: {} of cell {} must be {}, got {} {}",
                                          quantity, c, expected, v, unit));
    }
  }
}

}  // namespace

void validate(const SolidLayer& layer, std::size_t cells) {
  check_array(layer.depth, "depth", "m", cells, false, Range::non_negative);
  check_array(layer.velocity_x, "velocity_x", "m/s", cells, false, Range::any);
  check_array(layer.velocity_y, "velocity_y", "m/s", cells, false, Range::any);
  check_array(layer.density, "density", "kg/m^3", cells, false, Range::positive);
  check_array(layer.structured_share, "structured_share", "", cells, false, Range::fraction);
  check_array(layer.grain_size, "grain_size", "m", cells, true, Range::positive);
  check_array(layer.released_fluid_rate, "released_fluid_rate", "m^3/s", cells, true,
              Range::non_negative);
}

SolidLayer layer_from_columns(const ColumnTotals& columns, std::size_t cells, double cell_area,
                              double window, double empty_density) {
  auto expect = [cells](std::span<const double> values, std::size_t per_cell, const char* name) {
    if (values.size() != per_cell * cells)
      throw cosim::InputError(
          fmt::format("solid layer: {} has {} values for {} cells", name, values.size(), cells));
  };
  expect(columns.volume, 1, "column_volume");
  expect(columns.mass, 1, "column_mass");
  expect(columns.momentum, 2, "column_momentum");
  expect(columns.structured_mass, 1, "structured_mass");
  if (!columns.released_volume.empty()) expect(columns.released_volume, 1, "released_fluid_volume");

  SolidLayer layer = empty_solid_layer(cells, empty_density);
  if (!columns.released_volume.empty()) layer.released_fluid_rate.assign(cells, 0.0);
  for (std::size_t c = 0; c < cells; ++c) {
    const double volume = columns.volume[c];
    if (!columns.released_volume.empty())
      layer.released_fluid_rate[c] = columns.released_volume[c] / window;
    if (!(volume > 0.0)) {
      if (volume < 0.0 || !std::isfinite(volume)) layer.depth[c] = volume;  // validate() names it
      continue;
    }
    const double mass = columns.mass[c];
    layer.depth[c] = volume / cell_area;
    layer.density[c] = mass / volume;
    layer.velocity_x[c] = columns.momentum[2 * c] / mass;
    layer.velocity_y[c] = columns.momentum[2 * c + 1] / mass;
    layer.structured_share[c] = std::clamp(columns.structured_mass[c] / mass, 0.0, 1.0);
  }
  validate(layer, cells);
  return layer;
}

}  // namespace swe

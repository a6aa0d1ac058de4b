#pragma once

#include <cstdint>
#include <span>

namespace ice {

// What an empty cell (bulk density at most the threshold) reports as its
// specific value, where q / rhobar has no meaning.
enum class EmptyCell : std::uint8_t {
  keep_previous,  // the value `specific` held before the call (last step's)
  zero,
};

// The primitive variables after advection, Tran et al., MPMICE, eqs. 81-84.
// The advected fields are densities per unit volume, so eq. 81 is the
// advected rhobar itself, and eqs. 82-84 are
//
//   specific_c = quantity_density_c / (bulk_density_c * per_unit),
//
// u = (rhobar u) / rhobar, v = (rhobar v) / rhobar with per_unit = 1, and
// T = (rhobar c_v T) / (rhobar c_v) with per_unit = c_v (eq. 83 as printed
// leaves c_v out; eq. 73 has it). Cells with bulk_density <= empty_density
// follow `empty`. Throws std::invalid_argument for spans of different sizes
// or a non-positive per_unit.
void specific_values(std::span<const double> quantity_density, std::span<const double> bulk_density,
                     double empty_density, EmptyCell empty, std::span<double> specific,
                     double per_unit = 1.0);

}  // namespace ice

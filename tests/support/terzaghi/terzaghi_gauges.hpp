#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/terzaghi_consolidation.hpp"

// The pore-pressure profile of a consolidating column, read from a gauges.csv
// of pressures along it, against Terzaghi's solution.
namespace cosim::testing {

using bench::oedometric_modulus;
using bench::TerzaghiColumn;

// A gauges.csv of pressures along a column: time in the first column, then
// per gauge `stride` columns, the pressure first; gauge g sits at height
// first_height + spacing g; `offset` (the ambient pressure) is subtracted.
struct PressureGauges {
  const std::vector<std::vector<double>>& rows;
  double first_height = 0.0;
  double spacing = 0.0;
  std::size_t stride = 1;
  double offset = 0.0;
};

struct ProfileError {
  double time = 0.0;      // of the row compared [s]
  double error = 0.0;     // largest |p - p_exact| over the gauges / p0
  double at = 0.0;        // its height [m]
  double measured = 0.0;  // p there [Pa]
  double exact = 0.0;     // the solution there [Pa]
};

// The row nearest to `time_factor` against the column's solution.
inline ProfileError largest_profile_error(const TerzaghiColumn& column, const PressureGauges& g,
                                          double time_factor) {
  const double t = column.time_of(time_factor);
  const auto row = std::min_element(g.rows.begin(), g.rows.end(), [&](auto& a, auto& b) {
    return std::abs(a[0] - t) < std::abs(b[0] - t);
  });
  ProfileError e;
  e.time = (*row)[0];
  const std::size_t count = (row->size() - 1) / g.stride;
  double worst = -1.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double z = g.first_height + g.spacing * static_cast<double>(k);
    const double p = (*row)[1 + g.stride * k] - g.offset;
    const double reference = column.excess_pressure(z, e.time);
    if (std::abs(p - reference) > worst) {
      worst = std::abs(p - reference);
      e.at = z;
      e.measured = p;
      e.exact = reference;
    }
  }
  e.error = worst / column.load;
  return e;
}

}  // namespace cosim::testing

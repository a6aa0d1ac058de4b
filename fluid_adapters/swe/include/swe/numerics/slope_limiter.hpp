#pragma once

#include <algorithm>
#include <cmath>

#include "swe/scheme.hpp"

namespace swe {

// Limited slope of a MUSCL reconstruction from the one-sided differences
// `a` (cell minus left neighbour) and `b` (right neighbour minus cell), both
// per unit length. Zero at extrema; TVD limiters of Sweby's region. On
// uniform cells, cell value +- slope dx/2 stays between the neighbours' values.
inline double limited_slope(LimiterKind kind, double a, double b) {
  if (kind == LimiterKind::none || a * b <= 0.0) return 0.0;
  switch (kind) {
    case LimiterKind::minmod:
      return std::abs(a) < std::abs(b) ? a : b;
    case LimiterKind::van_leer:
      return 2.0 * a * b / (a + b);
    case LimiterKind::monotonized_central:
      return std::copysign(std::min({2.0 * std::abs(a), 2.0 * std::abs(b), 0.5 * std::abs(a + b)}), a);
    case LimiterKind::none:
      break;
  }
  return 0.0;
}

}  // namespace swe

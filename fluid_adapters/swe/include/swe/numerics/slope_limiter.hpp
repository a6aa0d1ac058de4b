#pragma once

#include <algorithm>
#include <cmath>

#include "swe/scheme.hpp"

namespace swe {

// Limited slope of a MUSCL reconstruction from the one-sided differences
// `a` (cell minus left neighbour) and `b` (right neighbour minus cell), both
// per unit length. Zero at extrema; TVD limiters of Sweby's region (Sweby,
// SIAM J. Numer. Anal. 21, 1984). On
// uniform cells, cell value +- slope dx/2 stays between the neighbours' values.
//
// The limiter fixed at compile time, without branches: both sides of each
// choice are computed and one is kept, so loops over cells vectorise.
template <LimiterKind kind>
inline double limited_slope(double a, double b) {
  double slope = 0.0;
  if constexpr (kind == LimiterKind::minmod) {
    slope = std::abs(a) < std::abs(b) ? a : b;
  } else if constexpr (kind == LimiterKind::van_leer) {
    slope = 2.0 * a * b / (a + b);
  } else if constexpr (kind == LimiterKind::monotonized_central) {
    slope = std::copysign(
        std::min(std::min(2.0 * std::abs(a), 2.0 * std::abs(b)), 0.5 * std::abs(a + b)), a);
  }
  return a * b <= 0.0 ? 0.0 : slope;
}

// The same, with the limiter chosen at run time.
inline double limited_slope(LimiterKind kind, double a, double b) {
  switch (kind) {
    case LimiterKind::minmod:
      return limited_slope<LimiterKind::minmod>(a, b);
    case LimiterKind::van_leer:
      return limited_slope<LimiterKind::van_leer>(a, b);
    case LimiterKind::monotonized_central:
      return limited_slope<LimiterKind::monotonized_central>(a, b);
    case LimiterKind::none:
      break;
  }
  return 0.0;
}

}  // namespace swe

#pragma once

#include <algorithm>
#include <cmath>

#include "swe/scheme.hpp"

// swe::limited_slope (swe/numerics/slope_limiter.hpp) with the limiter fixed
// at compile time and the extremum test as a select instead of a return, so
// a loop over cells vectorises. Same operations, bitwise the same slopes.
namespace swe::solver_1d {

template <LimiterKind limiter>
inline double limited_slope_1d(double a, double b) {
  double slope = 0.0;
  if constexpr (limiter == LimiterKind::minmod) {
    slope = std::abs(a) < std::abs(b) ? a : b;
  } else if constexpr (limiter == LimiterKind::van_leer) {
    slope = 2.0 * a * b / (a + b);
  } else if constexpr (limiter == LimiterKind::monotonized_central) {
    slope = std::copysign(std::min(std::min(2.0 * std::abs(a), 2.0 * std::abs(b)), 0.5 * std::abs(a + b)), a);
  }
  return a * b <= 0.0 ? 0.0 : slope;
}

// The increment from the cell value to its upper face, from the limited
// slope of the differences to the neighbours (per unit length), scaled down
// so that both faces lie between the cell value and the neighbour's on that
// side: |increment| <= min(|d_l|, |d_r|), the slope having their sign. On
// non-uniform cells the limiter alone does not ensure this. Scaling the slope
// (instead of clipping one face) keeps the face mean at the cell mean, which
// the positivity of the hydrostatic scheme relies on.
template <LimiterKind limiter>
inline double face_increment(double d_l, double d_r, double inv_distance_l, double inv_distance_r,
                             double half_width) {
  const double slope = limited_slope_1d<limiter>(d_l * inv_distance_l, d_r * inv_distance_r);
  const double bound = std::min(std::abs(d_l), std::abs(d_r));
  const double increment = slope * half_width;
  return increment < -bound ? -bound : bound < increment ? bound : increment;
}

}  // namespace swe::solver_1d

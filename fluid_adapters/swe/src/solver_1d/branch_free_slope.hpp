#pragma once

#include <algorithm>
#include <cmath>

#include "swe/numerics/slope_limiter.hpp"

namespace swe::solver_1d {

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
  const double slope = swe::limited_slope<limiter>(d_l * inv_distance_l, d_r * inv_distance_r);
  const double bound = std::min(std::abs(d_l), std::abs(d_r));
  const double increment = slope * half_width;
  return increment < -bound ? -bound : bound < increment ? bound : increment;
}

}  // namespace swe::solver_1d

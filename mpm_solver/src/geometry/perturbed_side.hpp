#pragma once

#include <utility>

namespace mpm::geometry_detail {

// Side of point (px, py) relative to the directed line a -> b: +1 left,
// -1 right, never 0. The point is displaced by an infinitesimal
// (eps, eps^2) (simulation of simplicity), so a point on the line goes to
// the side the displacement points to:
//   det(p + d) = det(p) - (by - ay) eps + (bx - ax) eps^2.
// The determinant is computed with the endpoints in a fixed order, so
// side(a, b, p) == -side(b, a, p) bit for bit and neighbouring triangles or
// edges agree on every point.
inline int perturbed_side(double ax, double ay, double bx, double by, double px, double py) {
  const bool swapped = bx < ax || (bx == ax && by < ay);
  if (swapped) {
    std::swap(ax, bx);
    std::swap(ay, by);
  }
  const double det = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  int side;
  if (det != 0.0)
    side = det > 0.0 ? 1 : -1;
  else if (by != ay)
    side = by < ay ? 1 : -1;
  else
    side = bx > ax ? 1 : -1;
  return swapped ? -side : side;
}

}  // namespace mpm::geometry_detail

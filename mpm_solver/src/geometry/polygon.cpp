#include "mpm/geometry/polygon.hpp"

#include <cmath>
#include <string>

#include "cosim/error.hpp"
#include "perturbed_side.hpp"

namespace mpm {

Polygon::Polygon(std::vector<Vec<2>> vertices) : vertices_(std::move(vertices)) {
  if (vertices_.size() < 3)
    throw cosim::InputError("polygon needs at least 3 vertices, got " +
                            std::to_string(vertices_.size()));
  bounds_.lower = bounds_.upper = vertices_.front();
  for (const Vec<2>& v : vertices_) {
    if (!v.allFinite()) throw cosim::InputError("polygon vertex is not finite");
    bounds_.lower = bounds_.lower.cwiseMin(v);
    bounds_.upper = bounds_.upper.cwiseMax(v);
  }
  if (!(area() > 0.0)) throw cosim::InputError("polygon has zero area");
}

// Crossings of the ray from x to +x with the edges that straddle the line
// y = x_y + eps^2: an edge from `low` up to `high` crosses to the right of
// x when x lies left of it.
bool Polygon::contains(const Vec<2>& x) const {
  bool inside = false;
  const std::size_t n = vertices_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec<2>& a = vertices_[j];
    const Vec<2>& b = vertices_[i];
    const bool a_above = a.y() > x.y(), b_above = b.y() > x.y();
    if (a_above == b_above) continue;
    const Vec<2>& low = a_above ? b : a;
    const Vec<2>& high = a_above ? a : b;
    if (geometry_detail::perturbed_side(low.x(), low.y(), high.x(), high.y(), x.x(), x.y()) > 0)
      inside = !inside;
  }
  return inside;
}

double Polygon::area() const {
  double twice = 0.0;
  const std::size_t n = vertices_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    twice += vertices_[j].x() * vertices_[i].y() - vertices_[i].x() * vertices_[j].y();
  return 0.5 * std::abs(twice);
}

}  // namespace mpm

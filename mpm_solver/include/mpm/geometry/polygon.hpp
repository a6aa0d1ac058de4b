#pragma once

#include <vector>

#include "mpm/core/tensor.hpp"
#include "mpm/geometry/box.hpp"

namespace mpm {

// A simple closed polygon in 2D, vertices in order (either orientation; the
// last connects to the first). Inside means an odd number of edge crossings
// of the ray from x towards +x (even-odd rule), decided exactly for points
// on edges and vertices: x is displaced by an infinitesimal (eps, eps^2), so
// polygons that share an edge never both claim a point on it.
class Polygon {
 public:
  // Throws cosim::InputError for fewer than 3 vertices, non-finite
  // coordinates or zero area.
  explicit Polygon(std::vector<Vec<2>> vertices);

  bool contains(const Vec<2>& x) const;
  const Box<2>& bounding_box() const { return bounds_; }
  double area() const;  // shoelace formula, positive
  const std::vector<Vec<2>>& vertices() const { return vertices_; }

 private:
  std::vector<Vec<2>> vertices_;
  Box<2> bounds_;
};

}  // namespace mpm

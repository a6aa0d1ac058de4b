#pragma once

#include <array>
#include <vector>

#include "mpm/core/tensor.hpp"
#include "mpm/geometry/box.hpp"

namespace mpm {

// A closed triangulated surface in 3D: vertices and triangles of vertex
// indices, consistently oriented (outward or inward). Inside means an
// odd number of crossings of the ray from x towards +x. Which triangles the
// ray meets is decided in the (y, z) projection with the query point
// displaced by an infinitesimal (eps, eps^2), so a ray through a shared edge
// or vertex is counted exactly once and grazing rays are counted zero or two
// times. Triangles are binned by their (y, z) bounds, so a query costs a few
// triangles, not all of them.
class Polyhedron {
 public:
  // Throws cosim::InputError for bad indices, degenerate input, or a
  // surface that is not closed and consistently oriented (some edge a -> b
  // not matched by an edge b -> a of another triangle).
  Polyhedron(std::vector<Vec<3>> vertices, std::vector<std::array<int, 3>> triangles);

  bool contains(const Vec<3>& x) const;
  const Box<3>& bounding_box() const { return bounds_; }
  // Enclosed volume (divergence theorem), positive for either orientation.
  double volume() const;
  const std::vector<Vec<3>>& vertices() const { return vertices_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

 private:
  std::vector<Vec<3>> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  Box<3> bounds_;
  // Triangles per bin of the (y, z) bounding rectangle, CSR layout.
  int bins_y_ = 1, bins_z_ = 1;
  std::vector<int> bin_start_, bin_triangles_;
  int bin_y(double y) const;
  int bin_z(double z) const;
};

}  // namespace mpm

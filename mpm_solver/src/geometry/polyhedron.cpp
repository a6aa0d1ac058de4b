#include "mpm/geometry/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "cosim/error.hpp"
#include "perturbed_side.hpp"

namespace mpm {

Polyhedron::Polyhedron(std::vector<Vec<3>> vertices, std::vector<std::array<int, 3>> triangles)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  if (vertices_.size() < 4 || triangles_.size() < 4)
    throw cosim::InputError("polyhedron needs at least 4 vertices and 4 triangles");
  bounds_.lower = bounds_.upper = vertices_.front();
  for (const Vec<3>& v : vertices_) {
    if (!v.allFinite()) throw cosim::InputError("polyhedron vertex is not finite");
    bounds_.lower = bounds_.lower.cwiseMin(v);
    bounds_.upper = bounds_.upper.cwiseMax(v);
  }
  // Closed and consistently oriented: each edge a -> b of a triangle is
  // matched by b -> a of another.
  std::map<std::pair<int, int>, int>
      edge_balance;  // (min, max) -> count(min->max) - count(max->min)
  const int n = static_cast<int>(vertices_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= n)
        throw cosim::InputError("polyhedron triangle " + std::to_string(t) + " refers to vertex " +
                                std::to_string(tri[k]) + " of " + std::to_string(n));
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
      throw cosim::InputError("polyhedron triangle " + std::to_string(t) + " repeats a vertex");
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      edge_balance[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
    }
  }
  for (const auto& [edge, balance] : edge_balance) {
    if (balance != 0)
      throw cosim::InputError(
          "polyhedron surface is not closed and consistently oriented at edge (" +
          std::to_string(edge.first) + ", " + std::to_string(edge.second) + ")");
  }
  if (!(volume() > 0.0)) throw cosim::InputError("polyhedron encloses no volume");

  // Bin the triangles by their (y, z) bounds on about sqrt(T) x sqrt(T) bins.
  const int per_direction =
      std::clamp(static_cast<int>(std::sqrt(static_cast<double>(triangles_.size()))), 1, 256);
  bins_y_ = bounds_.upper.y() > bounds_.lower.y() ? per_direction : 1;
  bins_z_ = bounds_.upper.z() > bounds_.lower.z() ? per_direction : 1;
  const std::size_t bin_count =
      static_cast<std::size_t>(bins_y_) * static_cast<std::size_t>(bins_z_);
  std::vector<std::array<int, 4>> ranges(triangles_.size());  // y0, y1, z0, z1
  std::vector<int> count(bin_count, 0);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Vec<3>& a = vertices_[static_cast<std::size_t>(tri[0])];
    const Vec<3>& b = vertices_[static_cast<std::size_t>(tri[1])];
    const Vec<3>& c = vertices_[static_cast<std::size_t>(tri[2])];
    ranges[t] = {bin_y(std::min({a.y(), b.y(), c.y()})), bin_y(std::max({a.y(), b.y(), c.y()})),
                 bin_z(std::min({a.z(), b.z(), c.z()})), bin_z(std::max({a.z(), b.z(), c.z()}))};
    for (int j = ranges[t][2]; j <= ranges[t][3]; ++j)
      for (int i = ranges[t][0]; i <= ranges[t][1]; ++i)
        ++count[static_cast<std::size_t>(j * bins_y_ + i)];
  }
  bin_start_.assign(bin_count + 1, 0);
  for (std::size_t b = 0; b < bin_count; ++b) bin_start_[b + 1] = bin_start_[b] + count[b];
  bin_triangles_.resize(static_cast<std::size_t>(bin_start_.back()));
  std::vector<int> fill(bin_start_.begin(), bin_start_.end() - 1);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int j = ranges[t][2]; j <= ranges[t][3]; ++j)
      for (int i = ranges[t][0]; i <= ranges[t][1]; ++i)
        bin_triangles_[static_cast<std::size_t>(
            fill[static_cast<std::size_t>(j * bins_y_ + i)]++)] = static_cast<int>(t);
}

int Polyhedron::bin_y(double y) const {
  const double extent = bounds_.upper.y() - bounds_.lower.y();
  if (!(extent > 0.0)) return 0;
  return std::clamp(static_cast<int>((y - bounds_.lower.y()) / extent * bins_y_), 0, bins_y_ - 1);
}

int Polyhedron::bin_z(double z) const {
  const double extent = bounds_.upper.z() - bounds_.lower.z();
  if (!(extent > 0.0)) return 0;
  return std::clamp(static_cast<int>((z - bounds_.lower.z()) / extent * bins_z_), 0, bins_z_ - 1);
}

bool Polyhedron::contains(const Vec<3>& x) const {
  if ((x.array() < bounds_.lower.array()).any() || (x.array() > bounds_.upper.array()).any())
    return false;
  const std::size_t bin = static_cast<std::size_t>(bin_z(x.z()) * bins_y_ + bin_y(x.y()));
  bool inside = false;
  for (int k = bin_start_[bin]; k < bin_start_[bin + 1]; ++k) {
    const auto& tri =
        triangles_[static_cast<std::size_t>(bin_triangles_[static_cast<std::size_t>(k)])];
    const Vec<3>& a = vertices_[static_cast<std::size_t>(tri[0])];
    const Vec<3>& b = vertices_[static_cast<std::size_t>(tri[1])];
    const Vec<3>& c = vertices_[static_cast<std::size_t>(tri[2])];
    // Does the ray's (y, z) lie in the projected triangle? (all three sides
    // equal, for either orientation)
    using geometry_detail::perturbed_side;
    const int s0 = perturbed_side(a.y(), a.z(), b.y(), b.z(), x.y(), x.z());
    const int s1 = perturbed_side(b.y(), b.z(), c.y(), c.z(), x.y(), x.z());
    if (s0 != s1) continue;
    const int s2 = perturbed_side(c.y(), c.z(), a.y(), a.z(), x.y(), x.z());
    if (s1 != s2) continue;
    // Where the ray meets the triangle's plane n . (q - a) = 0.
    const Vec<3> normal = (b - a).cross(c - a);
    if (normal.x() == 0.0) continue;  // parallel to the ray (zero projected area)
    const double hit =
        a.x() - (normal.y() * (x.y() - a.y()) + normal.z() * (x.z() - a.z())) / normal.x();
    if (hit > x.x()) inside = !inside;
  }
  return inside;
}

double Polyhedron::volume() const {
  double six = 0.0;
  for (const auto& tri : triangles_) {
    const Vec<3>& a = vertices_[static_cast<std::size_t>(tri[0])];
    const Vec<3>& b = vertices_[static_cast<std::size_t>(tri[1])];
    const Vec<3>& c = vertices_[static_cast<std::size_t>(tri[2])];
    six += a.dot(b.cross(c));
  }
  return std::abs(six) / 6.0;
}

}  // namespace mpm

#include "case/body_seeding.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>

namespace mpm::case_loading {

namespace {

Vec3d point(const std::vector<double>& v) {
  Vec3d x = Vec3d::Zero();
  for (std::size_t d = 0; d < v.size() && d < 3; ++d) x[static_cast<Eigen::Index>(d)] = v[d];
  return x;
}

// Even-odd rule.
bool inside_polygon(const std::vector<Vec3d>& vertices, const Vec3d& x) {
  bool inside = false;
  for (std::size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    const Vec3d& a = vertices[i];
    const Vec3d& b = vertices[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

}  // namespace

SeededBody seed_body(const cosim::config::Node& geometry, int dimension, const GridSpec& grid,
                     const std::array<int, 3>& particles_per_cell, Seeding seeding) {
  std::function<bool(const Vec3d&)> contains;
  Vec3d lower = Vec3d::Zero();  // bounding box of the region
  Vec3d upper = Vec3d::Zero();
  if (auto box = geometry.find("box")) {
    const Vec3d lo = point((*box)["min"].as<std::vector<double>>());
    const Vec3d hi = point((*box)["max"].as<std::vector<double>>());
    for (int d = 0; d < dimension; ++d)
      if (!(lo[d] < hi[d])) (*box)["max"].fail("box max must exceed min in every direction");
    lower = lo;
    upper = hi;
    contains = [lo, hi, dimension](const Vec3d& x) {
      for (int d = 0; d < dimension; ++d)
        if (x[d] < lo[d] || x[d] >= hi[d]) return false;
      return true;
    };
  } else if (auto polygon = geometry.find("polygon")) {
    if (dimension != 2) polygon->fail_at_key("a polygon needs dimension: 2");
    std::vector<Vec3d> vertices;
    for (const auto& v : polygon->items()) vertices.push_back(point(v.as<std::vector<double>>()));
    lower = upper = vertices.front();
    for (const auto& v : vertices) {
      lower = lower.cwiseMin(v);
      upper = upper.cwiseMax(v);
    }
    contains = [vertices](const Vec3d& x) { return inside_polygon(vertices, x); };
  } else {
    geometry.fail("only box and polygon geometries are available until the geometry module lands");
  }
  if (seeding != Seeding::regular) geometry.fail("r2 seeding needs the geometry module");

  SeededBody body;
  Vec3d step = Vec3d::Ones();
  double volume = 1.0;
  for (int d = 0; d < dimension; ++d) {
    step[d] = grid.spacing[d] / particles_per_cell[static_cast<std::size_t>(d)];
    volume *= step[d];
  }
  // The lattice of cell-aligned sub-cell centres over the region's bounding box.
  std::array<int, 3> first{0, 0, 0};
  std::array<int, 3> last{0, 0, 0};
  for (int d = 0; d < dimension; ++d) {
    first[static_cast<std::size_t>(d)] =
        static_cast<int>(std::floor((lower[d] - grid.origin[d]) / step[d]));
    last[static_cast<std::size_t>(d)] =
        static_cast<int>(std::ceil((upper[d] - grid.origin[d]) / step[d]));
  }
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i) {
        Vec3d x = grid.origin + Vec3d(i + 0.5, j + 0.5, k + 0.5).cwiseProduct(step);
        if (dimension == 2) x.z() = 0.0;
        if (!contains(x)) continue;
        body.positions.push_back(x);
        body.volumes.push_back(volume);
        Vec3d h = 0.5 * step;
        if (dimension == 2) h.z() = 0.0;
        body.half_lengths.push_back(h);
      }
  return body;
}

}  // namespace mpm::case_loading

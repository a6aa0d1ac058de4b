#include "swe/case/initial_condition.hpp"

#include <algorithm>
#include <cmath>

namespace swe {

bool InitialRegion::contains(const cosim::Vec3& x, int dimension) const {
  switch (shape) {
    case Shape::everywhere:
      return true;
    case Shape::box:
      for (int d = 0; d < dimension; ++d) {
        const auto k = static_cast<std::size_t>(d);
        if (x[k] < min[k] || x[k] > max[k]) return false;
      }
      return true;
    case Shape::circle:
      return std::hypot(x[0] - centre[0], x[1] - centre[1]) <= radius;
  }
  return false;
}

void InitialCondition::lay(const cosim::Mesh& cells, std::span<const double> bed,
                           std::vector<double>& h, std::vector<double>& hu,
                           std::vector<double>& hv) const {
  const std::size_t n = cells.size();
  const int dim = cells.dimension();
  h.assign(n, 0.0);
  hu.assign(n, 0.0);
  hv.assign(dim == 2 ? n : 0, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const cosim::Vec3 x = cells.position(c);
    const InitialRegion* applies = nullptr;
    for (const InitialRegion& r : regions)
      if (r.contains(x, dim)) applies = &r;
    if (!applies) continue;
    h[c] = applies->free_surface ? std::max(0.0, applies->level - bed[c]) : applies->level;
    hu[c] = h[c] * applies->velocity[0];
    if (dim == 2) hv[c] = h[c] * applies->velocity[1];
  }
}

}  // namespace swe

#include "mapping/build_operator.hpp"

#include <string>
#include <utility>
#include <variant>

#include "cosim/error.hpp"
#include "kernel_map.hpp"
#include "overlap_map.hpp"

namespace cosim::mapping {
namespace {

bool is_structured(const Mesh& m) {
  return m.kind() == MeshKind::uniform_grid || m.kind() == MeshKind::nonuniform_line;
}
bool is_cloud(const Mesh& m) {
  return m.kind() == MeshKind::point_cloud || m.kind() == MeshKind::cell_cloud;
}

// The same cloud: the same elements, at the same places, with the same volumes.
bool same_cloud(const Mesh& a, const Mesh& b) {
  if (a.kind() != b.kind()) return false;
  if (const auto* p = std::get_if<PointCloud>(&a.geometry)) {
    const auto& q = std::get<PointCloud>(b.geometry);
    return p->dim == q.dim && p->positions == q.positions && p->volumes == q.volumes;
  }
  if (const auto* c = std::get_if<CellCloud>(&a.geometry)) {
    const auto& d = std::get<CellCloud>(b.geometry);
    return c->dim == d.dim && c->centres == d.centres && c->volumes == d.volumes;
  }
  return false;
}

Operator identity(const Mesh& from, const Mesh& to, Constraint constraint) {
  const auto n = static_cast<Eigen::Index>(from.size());
  Weights weights(n, n);
  weights.setIdentity();
  return Operator(constraint, std::move(weights), from.name, to.name);
}

std::string describe(const Mesh& m) {
  return "'" + m.name + "' (" + to_string(m.kind()) + ", " + std::to_string(m.dimension()) + "D)";
}

[[noreturn]] void reject(const Mesh& from, const Mesh& to, Constraint c, const std::string& why) {
  throw InputError(std::string("no ") + to_string(c) + " mapping from mesh " + describe(from) +
                   " to mesh " + describe(to) + ": " + why);
}

}  // namespace

Operator build_operator(const Mesh& from, const Mesh& to, Constraint constraint,
                        const Options& options) {
  validate(from);
  validate(to);
  if (from.dimension() != to.dimension()) reject(from, to, constraint, "dimensions differ");
  if (is_structured(from) && is_structured(to))
    return detail::build_overlap_operator(from, to, constraint);
  const bool cloud_grid = is_cloud(from) && to.kind() == MeshKind::uniform_grid;
  const bool grid_cloud = from.kind() == MeshKind::uniform_grid && is_cloud(to);
  if (cloud_grid || grid_cloud)
    return detail::build_kernel_operator(from, to, constraint, options.kernel);
  if (same_cloud(from, to)) return identity(from, to, constraint);
  reject(from, to, constraint,
         "supported pairs are grid/line <-> grid/line and point/cell cloud <-> uniform grid "
         "(map through a uniform grid)");
}

}  // namespace cosim::mapping

#include "cosim/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"

namespace cosim {

Index3 UniformGrid::extent() const {
  Index3 n{1, 1, 1};
  const std::int64_t extra = location == GridLocation::node ? 1 : 0;
  for (int d = 0; d < dim; ++d) n[d] = cells[d] + extra;
  return n;
}

std::size_t UniformGrid::size() const {
  const Index3 n = extent();
  return static_cast<std::size_t>(n[0] * n[1] * n[2]);
}

std::size_t UniformGrid::flat(std::int64_t i, std::int64_t j, std::int64_t k) const {
  const Index3 n = extent();
  return static_cast<std::size_t>(i + n[0] * (j + n[1] * k));
}

Index3 UniformGrid::unflat(std::size_t flat_index) const {
  const Index3 n = extent();
  const auto f = static_cast<std::int64_t>(flat_index);
  return {f % n[0], (f / n[0]) % n[1], f / (n[0] * n[1])};
}

Vec3 UniformGrid::position(std::size_t flat_index) const {
  const Index3 ijk = unflat(flat_index);
  const double shift = location == GridLocation::cell ? 0.5 : 0.0;
  Vec3 x{0, 0, 0};
  for (int d = 0; d < dim; ++d)
    x[d] = origin[d] + (static_cast<double>(ijk[d]) + shift) * spacing[d];
  return x;
}

double UniformGrid::control_volume(std::size_t flat_index) const {
  const Index3 ijk = unflat(flat_index);
  double v = 1.0;
  for (int d = 0; d < dim; ++d) {
    double h = spacing[d];
    if (location == GridLocation::node && (ijk[d] == 0 || ijk[d] == cells[d])) h *= 0.5;
    v *= h;
  }
  return v;
}

Vec3 UniformGrid::upper() const {
  Vec3 x = origin;
  for (int d = 0; d < dim; ++d) x[d] += static_cast<double>(cells[d]) * spacing[d];
  return x;
}

Vec3 PointCloud::position(std::size_t p) const {
  Vec3 x{0, 0, 0};
  for (int d = 0; d < dim; ++d) x[d] = positions[p * dim + d];
  return x;
}

Vec3 CellCloud::centre(std::size_t c) const {
  Vec3 x{0, 0, 0};
  for (int d = 0; d < dim; ++d) x[d] = centres[c * dim + d];
  return x;
}

int Mesh::dimension() const {
  return std::visit(
      [](const auto& g) -> int {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, NonUniformLine>)
          return 1;
        else
          return g.dim;
      },
      geometry);
}

std::size_t Mesh::size() const {
  return std::visit([](const auto& g) { return g.size(); }, geometry);
}

double Mesh::control_volume(std::size_t e) const {
  return std::visit(
      [e](const auto& g) -> double {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, UniformGrid>)
          return g.control_volume(e);
        else if constexpr (std::is_same_v<G, NonUniformLine>)
          return g.width(e);
        else
          return g.volumes[e];
      },
      geometry);
}

Vec3 Mesh::position(std::size_t e) const {
  return std::visit(
      [e](const auto& g) -> Vec3 {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, UniformGrid>)
          return g.position(e);
        else if constexpr (std::is_same_v<G, NonUniformLine>)
          return {g.centre(e), 0.0, 0.0};
        else if constexpr (std::is_same_v<G, PointCloud>)
          return g.position(e);
        else
          return g.centre(e);
      },
      geometry);
}

MeshPart MeshPart::box(const UniformGrid& grid, const Index3& lower, const Index3& upper) {
  const Index3 n = grid.extent();
  MeshPart part;
  for (int d = 0; d < 3; ++d)
    if (lower[d] < 0 || upper[d] > n[d] || lower[d] > upper[d])
      throw std::invalid_argument("MeshPart::box: the box is not inside the grid");
  part.elements.reserve(static_cast<std::size_t>((upper[0] - lower[0]) * (upper[1] - lower[1]) *
                                                 (upper[2] - lower[2])));
  for (std::int64_t k = lower[2]; k < upper[2]; ++k)
    for (std::int64_t j = lower[1]; j < upper[1]; ++j)
      for (std::int64_t i = lower[0]; i < upper[0]; ++i)
        part.elements.push_back(static_cast<std::int64_t>(grid.flat(i, j, k)));
  return part;
}

MeshPart MeshPart::box(const UniformGrid& grid, const Index3& lower, const Index3& upper,
                       const Index3& owned_lower, const Index3& owned_upper) {
  MeshPart part = box(grid, lower, upper);
  part.owned.reserve(part.size());
  for (const std::int64_t e : part.elements) {
    const Index3 at = grid.unflat(static_cast<std::size_t>(e));
    bool owned = true;
    for (int d = 0; d < 3; ++d) owned = owned && at[d] >= owned_lower[d] && at[d] < owned_upper[d];
    part.owned.push_back(owned ? 1 : 0);
  }
  return part;
}

bool MeshPart::has_ghosts() const {
  return std::find(owned.begin(), owned.end(), std::uint8_t{0}) != owned.end();
}

const char* to_string(MeshKind kind) {
  switch (kind) {
    case MeshKind::uniform_grid:
      return "uniform_grid";
    case MeshKind::nonuniform_line:
      return "nonuniform_line";
    case MeshKind::point_cloud:
      return "point_cloud";
    case MeshKind::cell_cloud:
      return "cell_cloud";
  }
  return "unknown";
}

const char* to_string(GridLocation location) {
  return location == GridLocation::cell ? "cell" : "node";
}

namespace {

[[noreturn]] void reject(const Mesh& mesh, const std::string& what) {
  throw InputError("mesh '" + mesh.name + "' (" + to_string(mesh.kind()) + "): " + what);
}

void check_dim(const Mesh& mesh, int dim) {
  if (dim < 1 || dim > 3) reject(mesh, "dimension " + std::to_string(dim) + " is not 1, 2 or 3");
}

template <class Cloud>
void check_cloud(const Mesh& mesh, const Cloud& cloud, const std::vector<double>& coords) {
  check_dim(mesh, cloud.dim);
  if (coords.size() != cloud.volumes.size() * static_cast<std::size_t>(cloud.dim))
    reject(mesh, std::to_string(coords.size()) + " coordinates for " +
                     std::to_string(cloud.volumes.size()) + " volumes in " +
                     std::to_string(cloud.dim) + "D");
  for (std::size_t p = 0; p < cloud.volumes.size(); ++p)
    if (!(cloud.volumes[p] > 0.0) || !std::isfinite(cloud.volumes[p]))
      reject(mesh, "volume of element " + std::to_string(p) + " is not positive and finite");
  for (std::size_t c = 0; c < coords.size(); ++c)
    if (!std::isfinite(coords[c]))
      reject(mesh, "non-finite coordinate at index " + std::to_string(c));
}

}  // namespace

void validate(const Mesh& mesh) {
  if (mesh.name.empty()) throw InputError("a mesh has an empty name");
  std::visit(
      [&mesh](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, UniformGrid>) {
          check_dim(mesh, g.dim);
          for (int d = 0; d < g.dim; ++d) {
            if (g.cells[d] < 1) reject(mesh, "cells[" + std::to_string(d) + "] must be >= 1");
            if (!(g.spacing[d] > 0.0) || !std::isfinite(g.spacing[d]))
              reject(mesh, "spacing[" + std::to_string(d) + "] must be positive and finite");
            if (!std::isfinite(g.origin[d]))
              reject(mesh, "origin[" + std::to_string(d) + "] is not finite");
          }
          // size() multiplies the counts: keep the product far from overflow.
          constexpr std::int64_t max_cells = std::int64_t{1} << 40;
          std::int64_t cells = 1;
          for (int d = 0; d < g.dim; ++d) {
            if (g.cells[d] > max_cells / cells) reject(mesh, "has more than 2^40 cells");
            cells *= g.cells[d];
          }
        } else if constexpr (std::is_same_v<G, NonUniformLine>) {
          if (g.edges.size() < 2) reject(mesh, "needs at least two edges");
          for (std::size_t i = 0; i + 1 < g.edges.size(); ++i)
            if (!(g.edges[i + 1] > g.edges[i]))
              reject(mesh, "edges must increase strictly (edge " + std::to_string(i + 1) + ")");
        } else if constexpr (std::is_same_v<G, PointCloud>) {
          check_cloud(mesh, g, g.positions);
        } else {
          check_cloud(mesh, g, g.centres);
        }
      },
      mesh.geometry);
}

}  // namespace cosim

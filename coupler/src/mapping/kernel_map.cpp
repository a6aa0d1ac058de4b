#include "kernel_map.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "bspline_kernel.hpp"
#include "cosim/error.hpp"
#include "sparse_weights.hpp"

namespace cosim::mapping::detail {
namespace {

struct CloudView {
  int dim = 3;
  std::span<const double> coords;  // element-major, dim per element
  std::span<const double> volumes;
  std::size_t size() const { return volumes.size(); }
};

CloudView cloud_view(const Mesh& mesh) {
  if (const auto* points = std::get_if<PointCloud>(&mesh.geometry))
    return {points->dim, points->positions, points->volumes};
  const auto& cells = std::get<CellCloud>(mesh.geometry);
  return {cells.dim, cells.centres, cells.volumes};
}

// Where the grid's values live, per direction: point i at first + i * step.
struct GridPoints {
  int dim = 1;
  std::array<double, 3> first{0, 0, 0};
  std::array<double, 3> step{1, 1, 1};
  std::array<std::int64_t, 3> extent{1, 1, 1};

  explicit GridPoints(const UniformGrid& g) : dim(g.dim), extent(g.extent()) {
    const double shift = g.location == GridLocation::cell ? 0.5 : 0.0;
    for (int d = 0; d < dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      step[u] = g.spacing[u];
      first[u] = g.origin[u] + shift * g.spacing[u];
    }
  }
  double grid_units(const double* x, int d) const {
    const auto u = static_cast<std::size_t>(d);
    return (x[d] - first[u]) / step[u];
  }
  std::size_t size() const { return static_cast<std::size_t>(extent[0] * extent[1] * extent[2]); }
};

struct CloudStencils {
  std::array<Stencil, 3> direction{};
  bool fallback = false;
  std::size_t count() const {
    return static_cast<std::size_t>(direction[0].count * direction[1].count * direction[2].count);
  }
};

CloudStencils stencils_of(const CloudView& cloud, const GridPoints& grid, std::size_t p,
                          Kernel kernel) {
  CloudStencils s;
  for (auto& st : s.direction) st = Stencil{0, 1, {1.0, 0.0, 0.0}, false};
  const double* x = cloud.coords.data() + p * static_cast<std::size_t>(cloud.dim);
  for (int d = 0; d < grid.dim; ++d) {
    const auto u = static_cast<std::size_t>(d);
    s.direction[u] = kernel_stencil(grid.grid_units(x, d), grid.extent[u], kernel);
    s.fallback = s.fallback || s.direction[u].fallback;
  }
  return s;
}

// Calls f(grid point, weight) for the tensor-product stencil of one cloud
// element, grid points in increasing order.
template <class F>
void for_each_weight(const CloudStencils& s, const GridPoints& grid, F&& f) {
  const std::int64_t nx = grid.extent[0];
  const std::int64_t nxy = nx * grid.extent[1];
  const Stencil& sx = s.direction[0];
  const Stencil& sy = s.direction[1];
  const Stencil& sz = s.direction[2];
  for (int c = 0; c < sz.count; ++c) {
    const double wz = sz.weight[static_cast<std::size_t>(c)];
    const std::int64_t oz = (sz.first + c) * nxy;
    for (int b = 0; b < sy.count; ++b) {
      const double wyz = sy.weight[static_cast<std::size_t>(b)] * wz;
      const std::int64_t oyz = oz + (sy.first + b) * nx;
      for (int a = 0; a < sx.count; ++a)
        f(static_cast<std::size_t>(oyz + sx.first + a),
          sx.weight[static_cast<std::size_t>(a)] * wyz);
    }
  }
}

// Interpolation weights N_I(x_p) / Σ_J N_J(x_p): cloud rows × grid columns,
// built directly in compressed form in two passes (count, fill): O(n).
Weights interpolation_weights(const CloudView& cloud, const GridPoints& grid, Kernel kernel) {
  const std::size_t n = cloud.size();
  std::size_t nonzeros = 0;
  for (std::size_t p = 0; p < n; ++p) nonzeros += stencils_of(cloud, grid, p, kernel).count();
  Weights w = allocate_weights(n, grid.size(), nonzeros);
  auto* outer = w.outerIndexPtr();
  auto* column = w.innerIndexPtr();
  double* value = w.valuePtr();
  Weights::StorageIndex e = 0;
  outer[0] = 0;
  for (std::size_t p = 0; p < n; ++p) {
    for_each_weight(stencils_of(cloud, grid, p, kernel), grid,
                    [&](std::size_t point, double weight) {
                      column[e] = static_cast<Weights::StorageIndex>(point);
                      value[e] = weight;
                      ++e;
                    });
    outer[p + 1] = e;
  }
  return w;
}

// The same weights laid out with grid rows (the transpose), each cloud
// element's column scaled by scale[p] (or 1), built directly by a counting
// sort on the grid point: no intermediate matrix. Counts the elements beyond
// every kernel (given to the nearest grid point).
Weights spreading_weights(const CloudView& cloud, const GridPoints& grid, Kernel kernel,
                          std::span<const double> scale, std::size_t& fallback_elements) {
  const std::size_t n = cloud.size();
  const std::size_t points = grid.size();
  std::vector<Weights::StorageIndex> next(points + 1, 0);
  std::size_t nonzeros = 0;
  fallback_elements = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const CloudStencils s = stencils_of(cloud, grid, p, kernel);
    nonzeros += s.count();
    if (s.fallback) ++fallback_elements;
    for_each_weight(s, grid, [&](std::size_t point, double) { ++next[point + 1]; });
  }
  Weights w = allocate_weights(points, n, nonzeros);
  auto* outer = w.outerIndexPtr();
  auto* column = w.innerIndexPtr();
  double* value = w.valuePtr();
  for (std::size_t i = 0; i < points; ++i) next[i + 1] += next[i];
  std::copy(next.begin(), next.end(), outer);
  for (std::size_t p = 0; p < n; ++p) {
    const double factor = scale.empty() ? 1.0 : scale[p];
    for_each_weight(stencils_of(cloud, grid, p, kernel), grid,
                    [&](std::size_t point, double weight) {
                      const auto e = next[point]++;
                      column[e] = static_cast<Weights::StorageIndex>(p);
                      value[e] = weight * factor;
                    });
  }
  return w;
}

// For each grid point, a cloud element near it: every element marks the grid
// point nearest to it (keeping the closest element), then a breadth-first
// search over face neighbours hands each unmarked point the element of the
// marked point it reaches first (nearest in grid steps).
std::vector<std::int64_t> nearest_cloud_elements(const CloudView& cloud, const GridPoints& grid) {
  const std::size_t points = grid.size();
  std::vector<std::int64_t> nearest(points, -1);
  std::vector<double> distance(points, std::numeric_limits<double>::infinity());
  for (std::size_t p = 0; p < cloud.size(); ++p) {
    const double* x = cloud.coords.data() + p * static_cast<std::size_t>(cloud.dim);
    std::int64_t flat = 0;
    std::int64_t stride = 1;
    double d2 = 0.0;
    for (int d = 0; d < grid.dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      const double s = grid.grid_units(x, d);
      const double i = std::clamp(std::round(s), 0.0, static_cast<double>(grid.extent[u] - 1));
      d2 += (s - i) * (s - i) * grid.step[u] * grid.step[u];
      flat += static_cast<std::int64_t>(i) * stride;
      stride *= grid.extent[u];
    }
    const auto f = static_cast<std::size_t>(flat);
    if (d2 < distance[f]) {
      distance[f] = d2;
      nearest[f] = static_cast<std::int64_t>(p);
    }
  }
  std::deque<std::size_t> queue;
  for (std::size_t f = 0; f < points; ++f)
    if (nearest[f] >= 0) queue.push_back(f);
  const std::array<std::int64_t, 3> stride{1, grid.extent[0], grid.extent[0] * grid.extent[1]};
  while (!queue.empty()) {
    const std::size_t f = queue.front();
    queue.pop_front();
    const auto flat = static_cast<std::int64_t>(f);
    for (int d = 0; d < grid.dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      const std::int64_t i = (flat / stride[u]) % grid.extent[u];
      for (const std::int64_t step : {-1, 1}) {
        if (i + step < 0 || i + step >= grid.extent[u]) continue;
        const auto g = static_cast<std::size_t>(flat + step * stride[u]);
        if (nearest[g] >= 0) continue;
        nearest[g] = nearest[f];
        queue.push_back(g);
      }
    }
  }
  return nearest;
}

// The averaging weights with each empty row given a single weight 1 on the
// nearest cloud element, so that their transpose keeps every grid amount.
Weights with_nearest_for_empty_rows(const Weights& average, const std::vector<std::size_t>& empty,
                                    const std::vector<std::int64_t>& nearest) {
  const auto rows = static_cast<std::size_t>(average.rows());
  Weights w = allocate_weights(rows, static_cast<std::size_t>(average.cols()),
                               static_cast<std::size_t>(average.nonZeros()) + empty.size());
  const auto* in_outer = average.outerIndexPtr();
  const auto* in_column = average.innerIndexPtr();
  const double* in_value = average.valuePtr();
  auto* outer = w.outerIndexPtr();
  auto* column = w.innerIndexPtr();
  double* value = w.valuePtr();
  Weights::StorageIndex e = 0;
  outer[0] = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    if (in_outer[r] == in_outer[r + 1]) {
      column[e] = static_cast<Weights::StorageIndex>(nearest[r]);
      value[e] = 1.0;
      ++e;
    }
    for (auto k = in_outer[r]; k < in_outer[r + 1]; ++k, ++e) {
      column[e] = in_column[k];
      value[e] = in_value[k];
    }
    outer[r + 1] = e;
  }
  return w;
}

}  // namespace

Operator build_kernel_operator(const Mesh& from, const Mesh& to, Constraint constraint,
                               Kernel kernel) {
  const bool cloud_to_grid =
      from.kind() == MeshKind::point_cloud || from.kind() == MeshKind::cell_cloud;
  const CloudView cloud = cloud_view(cloud_to_grid ? from : to);
  const GridPoints grid(std::get<UniformGrid>((cloud_to_grid ? to : from).geometry));

  if (!cloud_to_grid && constraint == Constraint::consistent)
    return Operator(constraint, interpolation_weights(cloud, grid, kernel), from.name, to.name);
  std::size_t outside = 0;
  if (cloud_to_grid && constraint == Constraint::conservative) {
    Weights spread = spreading_weights(cloud, grid, kernel, {}, outside);
    return Operator(constraint, std::move(spread), from.name, to.name, {}, outside);
  }

  // kernel- and volume-weighted average onto the grid:
  // W_Ip = V_p N_Ip / Σ_q V_q N_Iq, with N the renormalised interpolation weights
  Weights average = spreading_weights(cloud, grid, kernel, cloud.volumes, outside);
  std::vector<std::size_t> empty = normalise_rows(average);
  if (cloud_to_grid)
    return Operator(constraint, std::move(average), from.name, to.name, std::move(empty));

  // grid → cloud, conservative: the transpose of the cloud → grid average
  if (cloud.size() == 0)
    throw InputError("conservative mapping from '" + from.name + "' to the empty cloud '" +
                     to.name + "' cannot keep the total");
  const std::vector<std::int64_t> nearest = nearest_cloud_elements(cloud, grid);
  return Operator(constraint, transposed(with_nearest_for_empty_rows(average, empty, nearest)),
                  from.name, to.name, {}, empty.size());
}

}  // namespace cosim::mapping::detail

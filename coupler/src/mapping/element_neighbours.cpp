#include "element_neighbours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>

namespace cosim::mapping::detail {
namespace {

ElementNeighbours grid_neighbours(const UniformGrid& grid) {
  const Index3 n = grid.extent();
  const std::array<std::int64_t, 3> stride{1, n[0], n[0] * n[1]};
  ElementNeighbours g;
  const std::size_t size = grid.size();
  g.start.reserve(size + 1);
  g.neighbour.reserve(size * 2 * static_cast<std::size_t>(grid.dim));
  g.start.push_back(0);
  for (std::size_t e = 0; e < size; ++e) {
    const Index3 ijk = grid.unflat(e);
    for (int d = 0; d < grid.dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      if (ijk[u] > 0) g.neighbour.push_back(e - static_cast<std::size_t>(stride[u]));
      if (ijk[u] + 1 < n[u]) g.neighbour.push_back(e + static_cast<std::size_t>(stride[u]));
    }
    g.start.push_back(g.neighbour.size());
  }
  return g;
}

ElementNeighbours line_neighbours(std::size_t size) {
  ElementNeighbours g;
  g.start.push_back(0);
  for (std::size_t e = 0; e < size; ++e) {
    if (e > 0) g.neighbour.push_back(e - 1);
    if (e + 1 < size) g.neighbour.push_back(e + 1);
    g.start.push_back(g.neighbour.size());
  }
  return g;
}

ElementNeighbours cloud_neighbours(int dim, std::span<const double> coords,
                                   std::span<const double> volumes) {
  const std::size_t n = volumes.size();
  const auto dims = static_cast<std::size_t>(dim);
  ElementNeighbours g;
  g.start.assign(n + 1, 0);
  if (n == 0) return g;
  std::array<double, 3> lower{0, 0, 0};
  std::array<double, 3> upper{0, 0, 0};
  for (std::size_t d = 0; d < dims; ++d) {
    lower[d] = upper[d] = coords[d];
    for (std::size_t p = 0; p < n; ++p) {
      lower[d] = std::min(lower[d], coords[p * dims + d]);
      upper[d] = std::max(upper[d], coords[p * dims + d]);
    }
  }
  const double mean_volume =
      std::accumulate(volumes.begin(), volumes.end(), 0.0) / static_cast<double>(n);
  double bin = std::pow(mean_volume, 1.0 / dim);
  double box = 1.0;
  for (std::size_t d = 0; d < dims; ++d) box *= std::max(upper[d] - lower[d], bin);
  bin = std::max(bin, std::pow(box / (2.0 * static_cast<double>(n)), 1.0 / dim));
  std::array<std::int64_t, 3> bins{1, 1, 1};
  for (std::size_t d = 0; d < dims; ++d)
    bins[d] = static_cast<std::int64_t>(std::floor((upper[d] - lower[d]) / bin)) + 1;
  auto bin_of = [&](std::size_t p, std::size_t d) {
    const auto b = static_cast<std::int64_t>(std::floor((coords[p * dims + d] - lower[d]) / bin));
    return std::clamp<std::int64_t>(b, 0, bins[d] - 1);
  };
  const auto bin_count = static_cast<std::size_t>(bins[0] * bins[1] * bins[2]);
  std::vector<std::size_t> bin_start(bin_count + 1, 0);
  std::vector<std::size_t> element_bin(n);
  for (std::size_t p = 0; p < n; ++p) {
    std::int64_t flat = 0;
    for (std::size_t d = dims; d-- > 0;) flat = flat * bins[d] + bin_of(p, d);
    element_bin[p] = static_cast<std::size_t>(flat);
    ++bin_start[element_bin[p] + 1];
  }
  std::partial_sum(bin_start.begin(), bin_start.end(), bin_start.begin());
  std::vector<std::size_t> by_bin(n);
  std::vector<std::size_t> fill(bin_start.begin(), bin_start.end() - 1);
  for (std::size_t p = 0; p < n; ++p) by_bin[fill[element_bin[p]]++] = p;

  for (std::size_t p = 0; p < n; ++p) {
    std::array<std::int64_t, 3> b{0, 0, 0};
    for (std::size_t d = 0; d < dims; ++d) b[d] = bin_of(p, d);
    std::array<std::int64_t, 3> lo{0, 0, 0};
    std::array<std::int64_t, 3> hi{0, 0, 0};
    for (std::size_t d = 0; d < dims; ++d) {
      lo[d] = std::max<std::int64_t>(b[d] - 1, 0);
      hi[d] = std::min<std::int64_t>(b[d] + 1, bins[d] - 1);
    }
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
          const auto flat = static_cast<std::size_t>(i + bins[0] * (j + bins[1] * k));
          for (std::size_t q = bin_start[flat]; q < bin_start[flat + 1]; ++q)
            if (by_bin[q] != p) g.neighbour.push_back(by_bin[q]);
        }
    g.start[p + 1] = g.neighbour.size();
  }
  return g;
}

}  // namespace

ElementNeighbours element_neighbours(const Mesh& mesh) {
  if (const auto* grid = std::get_if<UniformGrid>(&mesh.geometry)) return grid_neighbours(*grid);
  if (const auto* line = std::get_if<NonUniformLine>(&mesh.geometry))
    return line_neighbours(line->size());
  if (const auto* points = std::get_if<PointCloud>(&mesh.geometry))
    return cloud_neighbours(points->dim, points->positions, points->volumes);
  const auto& cells = std::get<CellCloud>(mesh.geometry);
  return cloud_neighbours(cells.dim, cells.centres, cells.volumes);
}

}  // namespace cosim::mapping::detail

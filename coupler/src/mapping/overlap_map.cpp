#include "overlap_map.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sparse_weights.hpp"

namespace cosim::mapping::detail {
namespace {

// Control volumes of a structured mesh are tensor products of contiguous 1D
// intervals: interval i of direction d is [edges[d][i], edges[d][i + 1]].
using DirectionEdges = std::array<std::vector<double>, 3>;

std::vector<double> grid_edges(const UniformGrid& grid, int d) {
  const double x0 = grid.origin[d];
  const double h = grid.spacing[d];
  const std::int64_t n = grid.cells[d];
  std::vector<double> edges;
  edges.reserve(static_cast<std::size_t>(n + 2));
  edges.push_back(x0);
  if (grid.location == GridLocation::cell) {
    for (std::int64_t i = 1; i <= n; ++i) edges.push_back(x0 + static_cast<double>(i) * h);
  } else {
    // dual cells of the nodes, halved at both ends
    for (std::int64_t i = 0; i < n; ++i) edges.push_back(x0 + (static_cast<double>(i) + 0.5) * h);
    edges.push_back(x0 + static_cast<double>(n) * h);
  }
  return edges;
}

DirectionEdges control_intervals(const Mesh& mesh) {
  DirectionEdges edges{std::vector<double>{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}};
  if (const auto* line = std::get_if<NonUniformLine>(&mesh.geometry)) {
    edges[0] = line->edges;
  } else {
    const auto& grid = std::get<UniformGrid>(mesh.geometry);
    for (int d = 0; d < grid.dim; ++d) edges[static_cast<std::size_t>(d)] = grid_edges(grid, d);
  }
  return edges;
}

// One direction's factor of the weights: rows are target intervals, entries
// (source interval, weight) sorted by source.
struct Factor {
  std::vector<std::int64_t> row_start;
  std::vector<std::int64_t> source;
  std::vector<double> weight;
  std::int64_t unmatched_sources = 0;  // conservative: given to the nearest target interval
  std::size_t rows() const { return row_start.size() - 1; }
  std::size_t nonzeros() const { return source.size(); }
};

struct Overlap {
  std::int64_t target;
  std::int64_t source;
  double length;
};

// Overlap lengths of two sorted contiguous partitions, by one merge sweep.
std::vector<Overlap> overlaps(const std::vector<double>& target,
                              const std::vector<double>& source) {
  std::vector<Overlap> out;
  const auto n = static_cast<std::int64_t>(target.size()) - 1;
  const auto m = static_cast<std::int64_t>(source.size()) - 1;
  std::int64_t t = 0;
  std::int64_t s = 0;
  while (t < n && s < m) {
    const auto ti = static_cast<std::size_t>(t);
    const auto si = static_cast<std::size_t>(s);
    const double length =
        std::min(target[ti + 1], source[si + 1]) - std::max(target[ti], source[si]);
    if (length > 0.0) out.push_back({t, s, length});
    if (target[ti + 1] < source[si + 1]) {
      ++t;
    } else if (source[si + 1] < target[ti + 1]) {
      ++s;
    } else {
      ++t;
      ++s;
    }
  }
  return out;
}

Factor factor_from(std::vector<Overlap> entries, std::size_t rows) {
  std::sort(entries.begin(), entries.end(), [](const Overlap& a, const Overlap& b) {
    return a.target != b.target ? a.target < b.target : a.source < b.source;
  });
  Factor f;
  f.row_start.assign(rows + 1, 0);
  for (const Overlap& e : entries) ++f.row_start[static_cast<std::size_t>(e.target) + 1];
  for (std::size_t r = 0; r < rows; ++r) f.row_start[r + 1] += f.row_start[r];
  for (const Overlap& e : entries) {
    f.source.push_back(e.source);
    f.weight.push_back(e.length);
  }
  return f;
}

// Consistent: each target interval averages the source over the part of it
// the source covers (rows normalised; rows with no overlap stay empty).
Factor consistent_factor(const std::vector<double>& target, const std::vector<double>& source) {
  std::vector<Overlap> entries = overlaps(target, source);
  std::vector<double> covered(target.size() - 1, 0.0);
  for (const Overlap& e : entries) covered[static_cast<std::size_t>(e.target)] += e.length;
  for (Overlap& e : entries) e.length /= covered[static_cast<std::size_t>(e.target)];
  return factor_from(std::move(entries), target.size() - 1);
}

// Conservative: the transpose of the consistent factor of the reverse pair,
// i.e. each source interval shares its amount by overlap fraction (columns
// normalised). A source interval outside the target partition goes whole to
// the nearest end interval.
Factor conservative_factor(const std::vector<double>& target, const std::vector<double>& source) {
  std::vector<Overlap> entries = overlaps(target, source);
  const std::size_t sources = source.size() - 1;
  std::vector<double> matched(sources, 0.0);
  for (const Overlap& e : entries) matched[static_cast<std::size_t>(e.source)] += e.length;
  for (Overlap& e : entries) e.length /= matched[static_cast<std::size_t>(e.source)];
  const auto last_target = static_cast<std::int64_t>(target.size()) - 2;
  std::int64_t unmatched = 0;
  for (std::size_t s = 0; s < sources; ++s) {
    if (matched[s] > 0.0) continue;
    const double centre = 0.5 * (source[s] + source[s + 1]);
    const double target_centre = 0.5 * (target.front() + target.back());
    entries.push_back(
        {centre < target_centre ? 0 : last_target, static_cast<std::int64_t>(s), 1.0});
    ++unmatched;
  }
  Factor f = factor_from(std::move(entries), target.size() - 1);
  f.unmatched_sources = unmatched;
  return f;
}

// Weights of the tensor-product mesh: row (i, j, k) is the product of the
// direction factors' rows i, j and k; columns come out sorted.
Weights kronecker(const std::array<Factor, 3>& f, const std::array<std::size_t, 3>& source_extent) {
  const std::size_t rows = f[0].rows() * f[1].rows() * f[2].rows();
  const std::size_t cols = source_extent[0] * source_extent[1] * source_extent[2];
  const std::size_t nonzeros = f[0].nonzeros() * f[1].nonzeros() * f[2].nonzeros();
  Weights w = allocate_weights(rows, cols, nonzeros);
  auto* outer = w.outerIndexPtr();
  auto* column = w.innerIndexPtr();
  double* value = w.valuePtr();
  const auto sx = static_cast<std::int64_t>(source_extent[0]);
  const auto sxy = sx * static_cast<std::int64_t>(source_extent[1]);
  std::size_t row = 0;
  Weights::StorageIndex e = 0;
  outer[0] = 0;
  for (std::size_t k = 0; k < f[2].rows(); ++k) {
    for (std::size_t j = 0; j < f[1].rows(); ++j) {
      for (std::size_t i = 0; i < f[0].rows(); ++i) {
        for (auto c = f[2].row_start[k]; c < f[2].row_start[k + 1]; ++c) {
          const auto cz = static_cast<std::size_t>(c);
          const double wz = f[2].weight[cz];
          const std::int64_t oz = f[2].source[cz] * sxy;
          for (auto b = f[1].row_start[j]; b < f[1].row_start[j + 1]; ++b) {
            const auto by = static_cast<std::size_t>(b);
            const double wyz = f[1].weight[by] * wz;
            const std::int64_t oyz = oz + f[1].source[by] * sx;
            for (auto a = f[0].row_start[i]; a < f[0].row_start[i + 1]; ++a) {
              const auto ax = static_cast<std::size_t>(a);
              column[e] = static_cast<Weights::StorageIndex>(oyz + f[0].source[ax]);
              value[e] = f[0].weight[ax] * wyz;
              ++e;
            }
          }
        }
        outer[++row] = e;
      }
    }
  }
  return w;
}

}  // namespace

Operator build_overlap_operator(const Mesh& from, const Mesh& to, Constraint constraint) {
  const DirectionEdges source = control_intervals(from);
  const DirectionEdges target = control_intervals(to);
  std::array<Factor, 3> factors;
  std::array<std::size_t, 3> source_extent{};
  for (std::size_t d = 0; d < 3; ++d) {
    factors[d] = constraint == Constraint::consistent ? consistent_factor(target[d], source[d])
                                                      : conservative_factor(target[d], source[d]);
    source_extent[d] = source[d].size() - 1;
  }
  Weights weights = kronecker(factors, source_extent);

  std::vector<std::size_t> empty_targets;
  std::size_t fallback_sources = 0;
  if (constraint == Constraint::consistent) {
    const auto* outer = weights.outerIndexPtr();
    for (Eigen::Index r = 0; r < weights.rows(); ++r)
      if (outer[r] == outer[r + 1]) empty_targets.push_back(static_cast<std::size_t>(r));
  } else {
    std::size_t matched = 1;
    for (std::size_t d = 0; d < 3; ++d)
      matched *= source_extent[d] - static_cast<std::size_t>(factors[d].unmatched_sources);
    fallback_sources = from.size() - matched;
  }
  return Operator(constraint, std::move(weights), from.name, to.name, std::move(empty_targets),
                  fallback_sources);
}

}  // namespace cosim::mapping::detail

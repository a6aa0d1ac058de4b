#pragma once

#include <cmath>
#include <vector>

#include "swe/solver_1d.hpp"

namespace swe_test {

// Edges of n cells on [a, b] whose widths vary smoothly by a factor ~3 with a
// jump in the middle: non-uniform enough to break anything that assumes a
// constant spacing.
inline std::vector<double> uneven_edges(std::size_t n, double a, double b) {
  std::vector<double> w(n);
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(n);
    w[i] = (1.0 + 0.5 * std::sin(7.0 * s)) * (i < n / 2 ? 1.0 : 1.7);
    total += w[i];
  }
  std::vector<double> edges{a};
  for (std::size_t i = 0; i < n; ++i) edges.push_back(edges.back() + w[i] * (b - a) / total);
  edges.back() = b;
  return edges;
}

inline std::vector<double> uniform_edges(std::size_t n, double a, double b) {
  std::vector<double> edges(n + 1);
  for (std::size_t i = 0; i <= n; ++i)
    edges[i] = a + (b - a) * static_cast<double>(i) / static_cast<double>(n);
  return edges;
}

inline std::vector<double> centres(const std::vector<double>& edges) {
  std::vector<double> c(edges.size() - 1);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = 0.5 * (edges[i] + edges[i + 1]);
  return c;
}

inline swe::Boundaries1d walls() {
  return {{swe::BoundaryKind::wall, 0.0}, {swe::BoundaryKind::wall, 0.0}};
}

inline double max_abs_velocity(const swe::Solver& s) {
  double m = 0.0;
  for (std::size_t i = 0; i < s.cell_count(); ++i) {
    if (s.depth()[i] >= s.physics().dry_depth)
      m = std::max(m, std::abs(s.discharge_x()[i] / s.depth()[i]));
  }
  return m;
}

}  // namespace swe_test

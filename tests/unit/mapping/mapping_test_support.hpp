#pragma once

#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "cosim/mesh.hpp"
#include "mapping/operator.hpp"

// Random geometries and the measures the mapping property tests share.
namespace cosim::mapping::testing {

inline double sum(std::span<const double> v) {
  double s = 0.0;
  for (const double x : v) s += x;
  return s;
}

inline double relative_difference(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

inline std::vector<double> random_values(std::size_t n, std::mt19937_64& rng, double lo = 0.1,
                                         double hi = 2.0) {
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng);
  return v;
}

inline UniformGrid random_grid(int dim, GridLocation location, std::mt19937_64& rng,
                               double offset_range, std::int64_t max_cells) {
  std::uniform_real_distribution<double> offset(-offset_range, offset_range);
  std::uniform_int_distribution<std::int64_t> cells(1, max_cells);
  UniformGrid g;
  g.dim = dim;
  g.location = location;
  for (int d = 0; d < dim; ++d) {
    const auto u = static_cast<std::size_t>(d);
    g.cells[u] = cells(rng);
    g.spacing[u] = 1.0 / static_cast<double>(g.cells[u]) * (1.0 + offset(rng));
    g.origin[u] = offset(rng);
  }
  return g;
}

inline double max_row_sum_error(const Weights& w) {
  double worst = 0.0;
  for (Eigen::Index r = 0; r < w.rows(); ++r) {
    double s = 0.0;
    for (Weights::InnerIterator it(w, r); it; ++it) s += it.value();
    if (s != 0.0) worst = std::max(worst, std::abs(s - 1.0));
  }
  return worst;
}

inline double max_column_sum_error(const Weights& w) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(w.cols());
  for (Eigen::Index r = 0; r < w.rows(); ++r)
    for (Weights::InnerIterator it(w, r); it; ++it) s[it.col()] += it.value();
  return (s.array() - 1.0).abs().maxCoeff();
}

}  // namespace cosim::mapping::testing

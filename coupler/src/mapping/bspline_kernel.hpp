#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "mapping/constraint.hpp"

namespace cosim::mapping::detail {

// The grid points of one direction whose kernel covers a position, with their
// weights renormalised over the points that exist: points 0..n-1 sit at
// s = 0, 1, ..., n-1 in grid units. Entries are contiguous from `first`.
struct Stencil {
  std::int64_t first = 0;
  int count = 0;
  std::array<double, 3> weight{};
  bool fallback = false;  // beyond every kernel: the nearest point takes it whole
};

// B-spline kernels of degree 1 (tent) and 2 on uniform knots, centred on the
// grid points; both are partitions of unity and reproduce linear functions
// where the whole stencil exists (Pan et al. 2021, App. A, eqs. 85–86 and
// properties (i)–(iii); eq. 88 builds 2D/3D kernels as tensor products).
inline Stencil kernel_stencil(double s, std::int64_t n, Kernel kernel) {
  const double last = static_cast<double>(n - 1);
  s = std::clamp(s, -4.0, last + 4.0);
  Stencil st;
  std::array<double, 3> w{};
  int width = 0;
  // s + 8 > 0, so truncation is floor (cheaper than std::floor without SSE4.1)
  const auto floor_of = [](double v) {
    return static_cast<double>(static_cast<std::int64_t>(v + 8.0) - 8);
  };
  if (kernel == Kernel::linear) {
    const double base = floor_of(s);
    const double f = s - base;
    st.first = static_cast<std::int64_t>(base);
    w = {1.0 - f, f, 0.0};
    width = 2;
  } else {
    const double centre = floor_of(s + 0.5);
    const double xi = s - centre;  // in [-1/2, 1/2)
    st.first = static_cast<std::int64_t>(centre) - 1;
    w = {0.5 * (0.5 - xi) * (0.5 - xi), 0.75 - xi * xi, 0.5 * (0.5 + xi) * (0.5 + xi)};
    width = 3;
  }
  int begin = 0;
  int end = width;
  while (begin < end && (st.first + begin < 0 || w[static_cast<std::size_t>(begin)] == 0.0))
    ++begin;
  while (end > begin && (st.first + end - 1 > n - 1 || w[static_cast<std::size_t>(end - 1)] == 0.0))
    --end;
  double sum = 0.0;
  for (int a = begin; a < end; ++a) sum += w[static_cast<std::size_t>(a)];
  if (!(sum > 0.0)) {
    st.first = static_cast<std::int64_t>(std::clamp(std::round(s), 0.0, last));
    st.count = 1;
    st.weight = {1.0, 0.0, 0.0};
    st.fallback = true;
    return st;
  }
  st.count = end - begin;
  for (int a = begin; a < end; ++a)
    st.weight[static_cast<std::size_t>(a - begin)] = w[static_cast<std::size_t>(a)] / sum;
  st.first += begin;
  return st;
}

}  // namespace cosim::mapping::detail

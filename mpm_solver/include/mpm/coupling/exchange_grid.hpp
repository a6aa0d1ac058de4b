#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "cosim/mesh.hpp"
#include "mpm/core/tensor.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm::coupling {

// The cell-centred grid the MPM exchanges porous-medium fields on (mesh
// "mpm_grid"): the MPM cells, or blocks of `factor` x `factor` of them. Two
// sets of weights tie a point to the cell centres:
//  - conservative (particle -> cell): the share of the particle's domain
//    (centre x, half lengths h) inside each cell, the part beyond the grid
//    going to the cell at that face; for a point without a domain, linear in
//    each direction between the two nearest centres, all weight to the last
//    centre beyond it. Non-negative and a partition of unity, so sums over
//    cells equal sums over particles. With the domains a body's solid fills
//    exactly the cells it covers (the linear weights put a quarter of a
//    surface row's volume in the empty cell above it).
//  - consistent (cell -> point): the same linear weights, extrapolated in the
//    half cell at a face, so a linear field and its gradient are reproduced
//    exactly everywhere.
template <int Dim>
struct ExchangeGrid {
  Vec<Dim> origin = Vec<Dim>::Zero();
  Vec<Dim> spacing = Vec<Dim>::Ones();
  std::array<int, Dim> cells{};

  // The MPM grid's cells grouped by `factor` per direction (the last block
  // of a direction extends past the grid when factor does not divide it).
  static ExchangeGrid covering(const Grid<Dim>& grid, int factor) {
    ExchangeGrid g;
    g.origin = grid.origin;
    for (int d = 0; d < Dim; ++d) {
      g.spacing[d] = grid.spacing[d] * factor;
      g.cells[static_cast<std::size_t>(d)] =
          (grid.cells[static_cast<std::size_t>(d)] + factor - 1) / factor;
    }
    return g;
  }

  std::size_t size() const {
    std::size_t n = 1;
    for (int c : cells) n *= static_cast<std::size_t>(c);
    return n;
  }
  double cell_volume() const { return spacing.prod(); }
  std::size_t flat(const std::array<int, Dim>& index) const {
    std::size_t f = 0, stride = 1;
    for (std::size_t d = 0; d < Dim; ++d) {
      f += static_cast<std::size_t>(index[d]) * stride;
      stride *= static_cast<std::size_t>(cells[d]);
    }
    return f;
  }
  Vec<Dim> centre(const std::array<int, Dim>& index) const {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d)
      x[d] = origin[d] + (index[static_cast<std::size_t>(d)] + 0.5) * spacing[d];
    return x;
  }

  // f(flat cell) for the cells of the 3^Dim block around `cell` (itself
  // included) that lie inside the grid.
  template <class F>
  void for_each_neighbour(std::size_t cell, F&& f) const {
    std::array<int, Dim> centre{};
    for (std::size_t d = 0, rest = cell; d < Dim; ++d) {
      centre[d] = static_cast<int>(rest % static_cast<std::size_t>(cells[d]));
      rest /= static_cast<std::size_t>(cells[d]);
    }
    int block = 1;
    for (int d = 0; d < Dim; ++d) block *= 3;
    for (int k = 0; k < block; ++k) {
      std::array<int, Dim> index{};
      bool inside = true;
      for (std::size_t d = 0, code = static_cast<std::size_t>(k); d < Dim; ++d, code /= 3) {
        index[d] = centre[d] + static_cast<int>(code % 3) - 1;
        inside = inside && index[d] >= 0 && index[d] < cells[d];
      }
      if (inside) f(flat(index));
    }
  }

  // f(flat cell) for the up to 2 Dim cells sharing a face with `cell`.
  template <class F>
  void for_each_face_neighbour(std::size_t cell, F&& f) const {
    std::size_t stride = 1;
    for (std::size_t d = 0; d < Dim; ++d) {
      const auto n = static_cast<std::size_t>(cells[d]);
      const std::size_t i = (cell / stride) % n;
      if (i > 0) f(cell - stride);
      if (i + 1 < n) f(cell + stride);
      stride *= n;
    }
  }

  cosim::UniformGrid mesh() const {
    cosim::UniformGrid m;
    m.dim = Dim;
    for (std::size_t d = 0; d < Dim; ++d) {
      m.origin[d] = origin[static_cast<int>(d)];
      m.spacing[d] = spacing[static_cast<int>(d)];
      m.cells[d] = cells[d];
    }
    m.location = cosim::GridLocation::cell;
    return m;
  }

  // f(flat cell, weight) for the cells a particle's domain overlaps.
  template <class F>
  void for_each_conservative(const Vec<Dim>& x, const Vec<Dim>& half_length, F&& f) const {
    constexpr int most = 8;  // cells per direction a domain may span
    std::array<int, Dim> first{};
    std::array<int, Dim> count{};
    double w[Dim][most];
    for (int d = 0; d < Dim; ++d) {
      const double h = half_length[d];
      const int n = cells[static_cast<std::size_t>(d)];
      const double lo = (x[d] - h - origin[d]) / spacing[d];
      const double hi = (x[d] + h - origin[d]) / spacing[d];
      const int i0 = std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1);
      const int i1 = std::clamp(static_cast<int>(std::floor(hi)), 0, n - 1);
      if (!(h > 0.0) || i1 - i0 >= most) return for_each_conservative(x, f);
      first[static_cast<std::size_t>(d)] = i0;
      count[static_cast<std::size_t>(d)] = i1 - i0 + 1;
      for (int i = i0; i <= i1; ++i) {
        const double a = i == 0 ? std::min(lo, 0.0) : static_cast<double>(i);
        const double b =
            i == n - 1 ? std::max(hi, static_cast<double>(n)) : static_cast<double>(i + 1);
        w[d][i - i0] = std::max(0.0, std::min(hi, b) - std::max(lo, a)) / (hi - lo);
      }
    }
    int total = 1;
    for (int d = 0; d < Dim; ++d) total *= count[static_cast<std::size_t>(d)];
    for (int k = 0; k < total; ++k) {
      std::array<int, Dim> index{};
      double weight = 1.0;
      for (int d = 0, rest = k; d < Dim; ++d) {
        const int j = rest % count[static_cast<std::size_t>(d)];
        rest /= count[static_cast<std::size_t>(d)];
        index[static_cast<std::size_t>(d)] = first[static_cast<std::size_t>(d)] + j;
        weight *= w[d][j];
      }
      if (weight > 0.0) f(flat(index), weight);
    }
  }

  // f(flat cell, weight) for the 2^Dim cells a point gives its quantities to.
  template <class F>
  void for_each_conservative(const Vec<Dim>& x, F&& f) const {
    std::array<int, Dim> first{};
    double w[Dim][2];
    for (int d = 0; d < Dim; ++d) {
      const int n = cells[static_cast<std::size_t>(d)];
      const double s = (x[d] - origin[d]) / spacing[d] - 0.5;
      int i = static_cast<int>(std::floor(s));
      double t = s - i;
      if (i < 0) {
        i = 0;
        t = 0.0;
      } else if (i >= n - 1) {
        i = n - 1;
        t = 0.0;
      }
      first[static_cast<std::size_t>(d)] = i;
      w[d][0] = 1.0 - t;
      w[d][1] = t;
    }
    visit(first, w, nullptr, [&](std::size_t c, double weight, const Vec<Dim>&) { f(c, weight); });
  }

  // f(flat cell, weight, gradient of the weight) of the multilinear
  // interpolant through the 2^Dim nearest centres (extrapolated at faces).
  template <class F>
  void for_each_consistent(const Vec<Dim>& x, F&& f) const {
    std::array<int, Dim> first{};
    double w[Dim][2];
    double dw[Dim][2];
    for (int d = 0; d < Dim; ++d) {
      const int n = cells[static_cast<std::size_t>(d)];
      if (n == 1) {
        first[static_cast<std::size_t>(d)] = 0;
        w[d][0] = 1.0;
        w[d][1] = 0.0;
        dw[d][0] = dw[d][1] = 0.0;
        continue;
      }
      const double s = (x[d] - origin[d]) / spacing[d] - 0.5;
      int i = static_cast<int>(std::floor(s));
      if (i < 0) i = 0;
      if (i > n - 2) i = n - 2;
      const double t = s - i;
      first[static_cast<std::size_t>(d)] = i;
      w[d][0] = 1.0 - t;
      w[d][1] = t;
      dw[d][0] = -1.0 / spacing[d];
      dw[d][1] = 1.0 / spacing[d];
    }
    visit(first, w, dw, f);
  }

 private:
  template <class F>
  void visit(const std::array<int, Dim>& first, const double (&w)[Dim][2], const double (*dw)[2],
             F&& f) const {
    constexpr int corners = 1 << Dim;
    for (int corner = 0; corner < corners; ++corner) {
      std::array<int, Dim> index{};
      double weight = 1.0;
      bool inside = true;
      for (int d = 0; d < Dim; ++d) {
        const int bit = (corner >> d) & 1;
        index[static_cast<std::size_t>(d)] = first[static_cast<std::size_t>(d)] + bit;
        if (index[static_cast<std::size_t>(d)] >= cells[static_cast<std::size_t>(d)])
          inside = false;
        weight *= w[d][bit];
      }
      if (!inside) continue;  // a zero weight past a single-cell direction
      Vec<Dim> gradient = Vec<Dim>::Zero();
      if (dw) {
        for (int d = 0; d < Dim; ++d) {
          double g = dw[d][(corner >> d) & 1];
          for (int e = 0; e < Dim; ++e)
            if (e != d) g *= w[e][(corner >> e) & 1];
          gradient[d] = g;
        }
      }
      f(flat(index), weight, gradient);
    }
  }
};

}  // namespace mpm::coupling

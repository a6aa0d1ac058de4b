#pragma once

#include <array>
#include <cstddef>

#include "mpm/core/tensor.hpp"
#include "mpm/shape/grid_geometry.hpp"
#include "mpm/shape/shape_kernel.hpp"

namespace mpm {

// The grid values one point touches and their weights: the tensor product
// N_ijk = N_i(x) N_j(y) N_k(z) of a one-dimensional kernel (Pan et al. 2021,
// eq. 88), with gradient (N_i' N_j N_k / h_x, N_i N_j' N_k / h_y, ...).
// Lives on the stack; evaluate once per point, then visit with for_each.
template <int Dim, ShapeKernel Kernel>
struct Stencil {
  static constexpr int support = Kernel::support;
  static constexpr int size = [] {
    int n = 1;
    for (int d = 0; d < Dim; ++d) n *= support;
    return n;
  }();

  // Filled by evaluate (left uninitialised: a stencil is made per point).
  std::array<int, Dim> first;
  std::array<std::size_t, Dim> stride;  // flat-index stride per direction (x fastest)
  double N[Dim][support];
  double dN[Dim][support];  // d/dx: kernel derivative over the spacing

  // x and half_length in metres.
  void evaluate(const Vec<Dim>& x, const Vec<Dim>& half_length, const GridGeometry<Dim>& grid) {
    std::size_t s = 1;
    for (int d = 0; d < Dim; ++d) {
      const double inv_h = 1.0 / grid.spacing[d];
      const double xi = (x[d] - grid.origin[d]) * inv_h;
      first[d] = Kernel::evaluate(xi, half_length[d] * inv_h, grid.cells[d], N[d], dN[d]);
      for (int k = 0; k < support; ++k) dN[d][k] *= inv_h;
      stride[d] = s;
      s *= static_cast<std::size_t>(Kernel::dofs(grid.cells[d]));
    }
  }

  // Flat index of the first value the point touches.
  std::size_t first_flat() const {
    std::size_t f = 0;
    for (int d = 0; d < Dim; ++d) f += static_cast<std::size_t>(first[d]) * stride[d];
    return f;
  }

  // f(flat value index, weight, gradient) for each of the support^Dim values.
  template <class F>
  void for_each(F&& f) const {
    const std::size_t base = first_flat();
    if constexpr (Dim == 1) {
      for (int i = 0; i < support; ++i) {
        Vec<1> g;
        g[0] = dN[0][i];
        f(base + static_cast<std::size_t>(i), N[0][i], g);
      }
    } else if constexpr (Dim == 2) {
      for (int j = 0; j < support; ++j) {
        const std::size_t row = base + static_cast<std::size_t>(j) * stride[1];
        for (int i = 0; i < support; ++i) {
          const Vec<2> g(dN[0][i] * N[1][j], N[0][i] * dN[1][j]);
          f(row + static_cast<std::size_t>(i), N[0][i] * N[1][j], g);
        }
      }
    } else {
      static_assert(Dim == 3, "Stencil supports 1, 2 and 3 dimensions");
      for (int k = 0; k < support; ++k) {
        const std::size_t plane = base + static_cast<std::size_t>(k) * stride[2];
        for (int j = 0; j < support; ++j) {
          const std::size_t row = plane + static_cast<std::size_t>(j) * stride[1];
          const double Njk = N[1][j] * N[2][k];
          const double dNj_Nk = dN[1][j] * N[2][k];
          const double Nj_dNk = N[1][j] * dN[2][k];
          for (int i = 0; i < support; ++i) {
            const Vec<3> g(dN[0][i] * Njk, N[0][i] * dNj_Nk, N[0][i] * Nj_dNk);
            f(row + static_cast<std::size_t>(i), N[0][i] * Njk, g);
          }
        }
      }
    }
  }
};

}  // namespace mpm

#pragma once

#include <algorithm>
#include <cmath>

// Quadratic B-spline on the open knot vector
// {0, 0, 0, 1, 2, ..., cells-1, cells, cells, cells} (Pan et al. 2021,
// App. A): cells + 2 basis functions, interpolatory at both faces.
//
// In cell c, with u = xi - c in [0, 1], the three non-zero functions are
// those of values c, c+1, c+2. Cox-de Boor (Pan et al. 2021, eqs. 85-86)
// unrolled over the knots c-1, c, c+1, c+2 around the cell, written in the
// local coordinate as a = (left knot) - c and b = (right knot) - c, gives
//
//   N_c   = (1 - u)^2 / (1 - a)
//   N_c+1 = (u - a)(1 - u) / (1 - a) + (b - u) u / b
//   N_c+2 = u^2 / b
//
// with a = -1, b = 2 inside the grid (the uniform quadratic B-spline); the
// first cell repeats its left knot (a = 0) and the last cell its right knot
// (b = 1). The derivatives follow from eq. 87 (or by differentiating).
namespace mpm {

struct QuadraticBsplineKernel {
  static constexpr int support = 3;

  static int dofs(int cells) { return cells + 2; }
  // Greville abscissae (mean of the two inner knots of each function):
  // 0, 0.5, 1.5, ..., cells - 0.5, cells.
  static double dof_coordinate(int i, int cells) {
    if (i == 0) return 0.0;
    if (i == cells + 1) return cells;
    return i - 0.5;
  }

  // xi is clamped to [0, cells].
  static int evaluate(double xi, double /*half_length*/, int cells, double* N, double* dN) {
    xi = std::clamp(xi, 0.0, static_cast<double>(cells));
    const int c = std::min(static_cast<int>(xi), cells - 1);
    const double u = xi - c;
    const double alpha = c == 0 ? 1.0 : 0.5;  // 1 / (1 - a)
    const double a = c == 0 ? 0.0 : -1.0;
    const double beta = c == cells - 1 ? 1.0 : 0.5;  // 1 / b
    const double b = c == cells - 1 ? 1.0 : 2.0;
    const double v = 1.0 - u;
    N[0] = alpha * v * v;
    N[2] = beta * u * u;
    N[1] = alpha * (u - a) * v + beta * (b - u) * u;
    dN[0] = -2.0 * alpha * v;
    dN[2] = 2.0 * beta * u;
    dN[1] = alpha * (v - (u - a)) + beta * (b - 2.0 * u);
    return c;
  }
};

}  // namespace mpm

#pragma once

#include <algorithm>
#include <cmath>

// C0 hat functions on the grid nodes (the standard MPM shape functions).
namespace mpm {

struct LinearKernel {
  static constexpr int support = 2;

  static int dofs(int cells) { return cells + 1; }
  static double dof_coordinate(int i, int /*cells*/) { return i; }

  // xi is clamped to [0, cells]; the node on the left of xi comes first.
  static int evaluate(double xi, double /*half_length*/, int cells, double* N, double* dN) {
    xi = std::clamp(xi, 0.0, static_cast<double>(cells));
    const int first = std::min(static_cast<int>(xi), cells - 1);
    const double u = xi - first;
    N[0] = 1.0 - u;
    N[1] = u;
    dN[0] = -1.0;
    dN[1] = 1.0;
    return first;
  }
};

}  // namespace mpm

#pragma once

#include <algorithm>
#include <cmath>

// uGIMP (Zheng et al., eq. 11; Bardenhagen and Kober): the hat function of
// each node averaged over the particle's undeformed domain [a, b] =
// [xi - l_p, xi + l_p]:
//
//   S_i(xi) = 1/(b - a) * integral_a^b hat(s - i) ds.
//
// Inside the grid this is exactly the five-piece formula of eq. 11. Near a
// face the domain is clipped to the grid, [a, b] = [xi - l_p, xi + l_p]
// intersected with [0, cells], so the weights still sum to 1 and no value
// outside the grid is touched; the weights then reproduce the centre of the
// clipped domain instead of xi.
//
// Away from the faces evaluate() uses the closed form of eq. 11 (interior());
// near a face the average over the clipped domain is evaluated without
// cancellation (so l_p -> 0 tends to the
// hat smoothly): the hat is linear between its kinks at i-1, i, i+1 with
// slope changes s = +1, -2, +1, and for a piecewise linear function
//
//   average over [a, b] = hat(mid) + sum_kinks s m^2 / (2 (b - a)),
//   m = max(0, min(b - k, k - a)),  mid = (a + b) / 2,
//
// since integral_a^b (x - k)_+ dx - (b - a)(mid - k)_+ = m^2 / 2.
namespace mpm {

struct GimpKernel {
  static constexpr int support = 3;

  static int dofs(int cells) { return cells + 1; }
  static double dof_coordinate(int i, int /*cells*/) { return i; }

  // half_length (in cells) is clamped to [0, 0.5], which keeps the domain
  // between the neighbours of the nearest node; 0 gives the linear hat.
  // xi is clamped to [0, cells]. Needs cells >= 2.
  static int evaluate(double xi, double half_length, int cells, double* N, double* dN) {
    const double last = static_cast<double>(cells);
    xi = std::clamp(xi, 0.0, last);
    const int nearest = static_cast<int>(xi + 0.5);
    const double lp = std::min(half_length, 0.5);
    if (lp > 0.0 && xi - lp >= 0.0 && xi + lp <= last && nearest >= 1 && nearest < cells)
        [[likely]] {
      interior(xi - nearest, lp, N, dN);
      return nearest - 1;
    }
    const int first = std::clamp(nearest - 1, 0, cells - 2);
    if (lp > 0.0)
      clipped(xi, lp, first, last, N, dN);
    else
      linear_hat(xi, first, cells, N, dN);
    return first;
  }

 private:
  // Eq. 11 for the nearest node and its two neighbours, with r = xi minus
  // the nearest node in [-1/2, 1/2]: the kink correction above with
  // m = max(0, l_p - |r|) gives
  //   S_left = max(0, -r) + m^2 / (4 l_p),  S_right = max(0, r) + m^2 / (4 l_p),
  //   S_centre = 1 - |r| - m^2 / (2 l_p).
  // (max(0, y) is written as (y + |y|) / 2: compilers turn std::max into a
  // branch on the region here, which mispredicts for scattered particles.)
  static void interior(double r, double lp, double* N, double* dN) {
    const double gap = lp - std::abs(r);
    const double m = 0.5 * (gap + std::abs(gap));
    const double inv_lp = 1.0 / lp;
    const double side = 0.25 * m * m * inv_lp;
    const double sign = std::copysign(1.0, r);
    const double dside = -0.5 * m * sign * inv_lp;
    const double right = 0.5 * (r + std::abs(r)), left = right - r;
    const double dright = 0.5 * (1.0 + sign), dleft = dright - 1.0;
    N[0] = left + side;
    N[1] = 1.0 - left - right - 2.0 * side;
    N[2] = right + side;
    dN[0] = dleft + dside;
    dN[1] = -sign - 2.0 * dside;
    dN[2] = dright + dside;
  }

  // The average over the clipped domain [a, b], by the kink correction.
  [[gnu::noinline]] static void clipped(double xi, double lp, int first, double last, double* N,
                                        double* dN) {
    const double a_free = xi - lp, b_free = xi + lp;
    const double a = std::max(a_free, 0.0), b = std::min(b_free, last);
    // d a / d xi and d b / d xi; a domain that ends exactly on the face is
    // not clipped (its weights reproduce x and so must its derivatives).
    const double da = a_free >= 0.0 ? 1.0 : 0.0;
    const double db = b_free <= last ? 1.0 : 0.0;
    const double length = b - a, dlength = db - da;
    const double mid = 0.5 * (a + b), dmid = 0.5 * (da + db);
    for (int k = 0; k < support; ++k) {
      const double node = first + k;
      const double r = mid - node;
      double n = hat(r), dn = hat_slope(r) * dmid;
      for (int kink = -1; kink <= 1; ++kink) {
        const double s = kink == 0 ? -2.0 : 1.0;
        const double p = b - (node + kink), q = (node + kink) - a;
        if (!(p > 0.0 && q > 0.0)) continue;
        // the tie p == q takes the side mid > kink, as hat_slope does
        const double m = std::min(p, q), dm = p < q ? db : -da;
        const double ratio = m / length;
        n += 0.5 * s * m * ratio;
        dn += s * ratio * (dm - 0.5 * m * dlength / length);
      }
      N[k] = n;
      dN[k] = dn;
    }
  }

  // l_p = 0: the linear hat; on a node its slope is the one of the cell
  // that holds xi, as for LinearKernel.
  [[gnu::noinline]] static void linear_hat(double xi, int first, int cells, double* N, double* dN) {
    const int cell = std::min(static_cast<int>(xi), cells - 1);
    for (int k = 0; k < support; ++k) {
      const int node = first + k;
      N[k] = hat(xi - node);
      dN[k] = node == cell ? -1.0 : node == cell + 1 ? 1.0 : 0.0;
    }
  }

  static double hat(double r) { return std::max(0.0, 1.0 - std::abs(r)); }
  // right derivative of the hat
  static double hat_slope(double r) {
    if (r >= -1.0 && r < 0.0) return 1.0;
    if (r >= 0.0 && r < 1.0) return -1.0;
    return 0.0;
  }
};

}  // namespace mpm

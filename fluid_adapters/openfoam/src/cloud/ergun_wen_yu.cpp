#include "openfoam/cloud/ergun_wen_yu.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cosim/error.hpp"

namespace openfoam {

namespace {

// Wen and Yu's Cd Re of a sphere (OpenFOAM's WenYuDrag).
double drag_times_reynolds(double re) {
  return re > 1000.0 ? 0.44 * re : 24.0 * (1.0 + 0.15 * std::pow(re, 0.687));
}

}  // namespace

double ergun_wen_yu_coefficient(const CloudDragInput& in, double d) {
  const double phi_s = in.solid_fraction;
  const double n = 1.0 - phi_s;
  const double re = in.fluid_density * in.relative_speed * d / in.viscosity;
  const double mu_over = in.viscosity / (n * d * d);
  if (n < 0.8) return phi_s * (150.0 * phi_s / n + 1.75 * re) * mu_over;
  return phi_s * 0.75 * drag_times_reynolds(n * re) * std::pow(n, -2.65) * mu_over;
}

double ergun_wen_yu_grain_size(const CloudDragInput& in, double coefficient) {
  double small = smallest_grain, large = largest_grain;
  const auto too_strong = [&](double d) { return ergun_wen_yu_coefficient(in, d) > coefficient; };
  if (!too_strong(small) || too_strong(large)) {
    throw cosim::NumericalError(fmt::format(
        "no parcel diameter in [{}, {}] m gives the drag coefficient {:.6g} kg/(m^3 s) at solid "
        "fraction {:.6g} and relative speed {:.6g} m/s (Ergun-Wen-Yu gives {:.6g} .. {:.6g})",
        small, large, coefficient, in.solid_fraction, in.relative_speed,
        ergun_wen_yu_coefficient(in, large), ergun_wen_yu_coefficient(in, small)));
  }
  // Bisection in log d: K_cloud falls with d (a jump at Re = 1000 included).
  while (large / small > 1.0 + 1e-12) {
    const double mid = std::sqrt(small * large);
    (too_strong(mid) ? small : large) = mid;
  }
  return std::sqrt(small * large);
}

double ergun_wen_yu_grain_size_within_range(const CloudDragInput& in, double coefficient) {
  if (ergun_wen_yu_coefficient(in, largest_grain) >= coefficient) return largest_grain;
  if (ergun_wen_yu_coefficient(in, smallest_grain) <= coefficient) return smallest_grain;
  return ergun_wen_yu_grain_size(in, coefficient);
}

}  // namespace openfoam

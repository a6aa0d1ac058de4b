#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

// Terzaghi's one-dimensional consolidation of a column of height h, drained
// at the top and impermeable at the bottom: the excess pore
// pressure under a load p0 applied at once (Pan et al. 2021, eq. 82; Tran
// et al., MPMICE, eq. 99 with z measured from the top), and under a load
// p0 f(t) ramped from zero over t_ramp, by superposition of the first:
//   p_ramp(z, t) = int_0^min(t, t_ramp) p(z, t - s) f'(s) ds,
// f linear (f' = 1 / t_ramp) or cycloidal (f = s/T - sin(2 pi s/T) / (2 pi),
// f' = (1 - cos(2 pi s/T)) / T), as the MPM's loads ramp.
namespace cosim::bench {

// The skeleton's constrained (oedometric) modulus E (1 - nu) / ((1 + nu) (1 - 2 nu)).
inline double oedometric_modulus(double youngs_modulus, double poisson_ratio) {
  const double nu = poisson_ratio;
  return youngs_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

struct TerzaghiColumn {
  double height = 1.0;          // h [m]
  double load = 1.0e4;          // p0 [Pa]
  double consolidation = 1.0;   // c_v [m^2/s]
  double ramp_time = 0.0;       // [s]; 0: the load at once
  bool cycloidal_ramp = false;  // the ramp's shape: linear, or cycloidal

  // z measured up from the impermeable bottom [m], t [s].
  double excess_pressure_step(double z, double t) const {
    if (t <= 0.0) return 0.0;
    const double time_factor = consolidation * t / (height * height);
    double sum = 0.0;
    for (int m = 1; m <= 2000; ++m) {
      const double k = (2 * m - 1) * std::numbers::pi / 2.0;
      const double term = std::exp(-k * k * time_factor);
      sum += (m % 2 == 1 ? 1.0 : -1.0) / (2 * m - 1) * std::cos(k * z / height) * term;
      if (term < 1e-16) break;
    }
    return 4.0 * load / std::numbers::pi * sum;
  }

  double excess_pressure(double z, double t) const {
    if (ramp_time <= 0.0) return excess_pressure_step(z, t);
    const double span = std::min(t, ramp_time);
    constexpr int intervals = 400;  // Simpson
    const auto rate = [&](double s) {
      return cycloidal_ramp ? (1.0 - std::cos(2.0 * std::numbers::pi * s / ramp_time)) / ramp_time
                            : 1.0 / ramp_time;
    };
    double sum = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double s = span * i / intervals;
      const double w = i == 0 || i == intervals ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += w * excess_pressure_step(z, t - s) * rate(s);
    }
    return sum * span / (3.0 * intervals);
  }

  double time_of(double time_factor) const { return time_factor * height * height / consolidation; }
};

}  // namespace cosim::bench

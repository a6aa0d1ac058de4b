#include "swe/two_phase/fluid_sources.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"

namespace swe {

SourceVolumes add_sources(const UniformSources& sources, const SolidLayer& layer, double cell_area,
                          double dt, std::span<double> h, std::span<double> hu,
                          std::span<double> hv) {
  auto rate_ok = [](double r) { return std::isfinite(r) && r >= 0.0; };
  if (!rate_ok(sources.rain_rate) || !rate_ok(sources.infiltration_rate) || !rate_ok(dt))
    throw cosim::InputError(fmt::format(
        "fluid sources: rain rate {} m/s, infiltration rate {} m/s and time step {} s must be "
        "finite and >= 0",
        sources.rain_rate, sources.infiltration_rate, dt));
  const std::size_t n = h.size();
  const bool planar = !hv.empty();
  const bool released = !layer.released_fluid_rate.empty();
  if (hu.size() != n || (planar && hv.size() != n) || (released && layer.size() != n))
    throw cosim::InputError(fmt::format(
        "fluid sources: {} depths, {} discharges and a solid layer of {} cells do not fit", n,
        hu.size(), layer.size()));
  const double rain = sources.rain_rate * dt, infiltration = sources.infiltration_rate * dt;
  double added = 0.0, infiltrated = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    double depth = h[c];
    if (released) {
      const double dh = layer.released_fluid_rate[c] * dt / cell_area;
      depth += dh;
      added += dh;
      hu[c] += dh * layer.velocity_x[c];
      if (planar) hv[c] += dh * layer.velocity_y[c];
    }
    depth += rain;
    added += rain;
    if (infiltration > 0.0 && depth > 0.0) {
      const double taken = std::min(infiltration, depth);
      const double kept = taken == depth ? 0.0 : (depth - taken) / depth;
      infiltrated += taken;
      depth = taken == depth ? 0.0 : depth - taken;
      hu[c] *= kept;
      if (planar) hv[c] *= kept;
    }
    h[c] = depth;
  }
  return {added * cell_area, infiltrated * cell_area};
}

}  // namespace swe

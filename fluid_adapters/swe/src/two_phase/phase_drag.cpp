#include "swe/two_phase/phase_drag.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"
#include "cosim/exchange/drag_relaxation.hpp"

namespace swe {

using cosim::exchange::DebrisMixture;

DebrisMixture cell_mixture(double solid_depth, double fluid_depth, double density,
                           double structured_share, const TwoPhaseParameters& parameters,
                           double fluid_density) {
  if (!(solid_depth > 0.0) || !(fluid_depth > 0.0))
    throw cosim::InputError(fmt::format(
        "two-phase mixture: solid depth {} m and fluid depth {} m must both be positive",
        solid_depth, fluid_depth));
  const double rho_s = parameters.solid_density;
  if (!(density > fluid_density && density <= rho_s))
    throw cosim::InputError(
        fmt::format("two-phase mixture: the solids' bulk density {} kg/m^3 must lie in (rho_f, "
                    "rho_s] = ({}, {}] kg/m^3",
                    density, fluid_density, rho_s));
  const double mixture_depth = solid_depth + fluid_depth;
  const double alpha_c = solid_depth / mixture_depth;
  const double phi = (density - fluid_density) / (rho_s - fluid_density);
  const double alpha_s = phi * alpha_c;
  DebrisMixture m;
  m.solid_fraction = alpha_s;
  m.confined_fluid_share = (1.0 - phi) * alpha_c / (1.0 - alpha_s);
  m.structured_solid_share = structured_share;
  m.solid_density = rho_s;
  m.fluid_density = fluid_density;
  m.fluid_viscosity = parameters.fluid_viscosity;
  return m;
}

void exchange_momentum(const TwoPhaseParameters& parameters, double fluid_density, double dry_depth,
                       double cell_area, double dt, std::span<const double> h, std::span<double> hu,
                       std::span<double> hv, SolidLayer& layer, std::span<double> impulse_x,
                       std::span<double> impulse_y) {
  const std::size_t n = layer.size();
  const bool planar = !hv.empty();
  if (h.size() != n || hu.size() != n || (planar && hv.size() != n) || impulse_x.size() != n ||
      (planar && impulse_y.size() != n))
    throw cosim::InputError(fmt::format(
        "two-phase drag: the fluid's arrays ({} depths) and the impulses do not fit the "
        "solid layer's {} cells",
        h.size(), n));
  const std::size_t components = planar ? 2 : 1;
  // Cells are independent: in parallel, the first failure (in cell order)
  // rethrown after the loop, as an exception may not leave it.
  const auto cells = static_cast<std::ptrdiff_t>(n);
  std::ptrdiff_t failed_cell = cells;
  std::string failure;
  cosim::exchange::GeneralisedDragParameters drag = parameters.drag;  // a copy per thread
#pragma omp parallel for schedule(static) firstprivate(drag)
  for (std::ptrdiff_t ci = 0; ci < cells; ++ci) {
    const auto c = static_cast<std::size_t>(ci);
    const double h_s = layer.depth[c], h_f = h[c];
    if (!(h_s > dry_depth && h_f > dry_depth)) continue;
    if (!layer.grain_size.empty()) drag.grain_size = layer.grain_size[c];
    const double rho_c = layer.density[c];
    const double mixture_depth = h_s + h_f;
    const double alpha_c = h_s / mixture_depth, alpha_u = h_f / mixture_depth;
    std::array<double, 2> u_c{layer.velocity_x[c], planar ? layer.velocity_y[c] : 0.0};
    std::array<double, 2> u_u{hu[c] / h_f, planar ? hv[c] / h_f : 0.0};
    std::array<double, 2> impulse{0.0, 0.0};
    const std::span<double> solid(u_c.data(), components), fluid(u_u.data(), components),
        given(impulse.data(), components);
    try {
      const DebrisMixture mixture =
          cell_mixture(h_s, h_f, rho_c, layer.structured_share[c], parameters, fluid_density);
      const double coefficient =
          cosim::exchange::generalised_drag_coefficient(mixture, drag, solid, fluid);
      cosim::exchange::DragRelaxation relaxation{
          .solid_weight = alpha_c * rho_c,
          .fluid_weight = alpha_u * fluid_density,
          .drag_coefficient = coefficient,
          .exponent = drag.exponent,
          .virtual_mass =
              parameters.virtual_mass
                  ? alpha_c * fluid_density * cosim::exchange::virtual_mass_coefficient(mixture)
                  : 0.0};
      cosim::exchange::relax_drag(relaxation, dt, solid, fluid, given);
    } catch (const std::exception& e) {
#pragma omp critical(two_phase_drag_failure)
      if (ci < failed_cell) {
        failed_cell = ci;
        failure = e.what();
      }
      continue;
    }
    layer.velocity_x[c] = u_c[0];
    hu[c] = h_f * u_u[0];
    impulse_x[c] += impulse[0] * mixture_depth * cell_area;
    if (planar) {
      layer.velocity_y[c] = u_c[1];
      hv[c] = h_f * u_u[1];
      impulse_y[c] += impulse[1] * mixture_depth * cell_area;
    }
  }
  if (failed_cell < cells)
    throw cosim::InputError(fmt::format("two-phase drag in cell {}: {}", failed_cell, failure));
}

}  // namespace swe

#include "exchange/two_phase_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "cosim/error.hpp"
#include "cosim/exchange/implicit_exchange.hpp"

namespace cosim::exchange {

namespace {

void require_size(std::size_t actual, std::size_t expected, const char* what) {
  if (actual != expected) {
    throw std::invalid_argument(
        fmt::format("two-phase exchange: '{}' has {} values, expected {}", what, actual, expected));
  }
}

void require_valid(bool ok, std::size_t cell, const char* what, double value) {
  if (!ok) {
    throw NumericalError(fmt::format("momentum exchange: cell {}: {} is {}", cell, what, value));
  }
}

}  // namespace

void exchange_two_phase(const DragLaw& law, int dim, double dt, std::span<const double> cell_volume,
                        const PhaseFields& fluid, const PhaseFields& solid,
                        const PorousMedium& medium, const TwoPhaseExchangeResult& result) {
  if (dim < 1 || dim > kMaxComponents) {
    throw std::invalid_argument(fmt::format("two-phase exchange: dim {} not in [1, 3]", dim));
  }
  if (!std::isfinite(dt) || dt < 0) {
    throw std::invalid_argument(fmt::format("two-phase exchange: time step {} must be >= 0", dt));
  }
  const std::size_t cells = cell_volume.size();
  const std::size_t vectors = cells * static_cast<std::size_t>(dim);
  require_size(fluid.bulk_density.size(), cells, "fluid bulk density");
  require_size(solid.bulk_density.size(), cells, "solid bulk density");
  require_size(fluid.velocity.size(), vectors, "fluid velocity");
  require_size(solid.velocity.size(), vectors, "solid velocity");
  require_size(medium.solid_fraction.size(), cells, "solid fraction");
  if (law.cell_input() == CellInput::grain_size) {
    require_size(medium.grain_size.size(), cells, "grain size");
  }
  if (law.cell_input() == CellInput::permeability) {
    require_size(medium.permeability.size(), cells, "permeability");
  }
  require_size(result.fluid_velocity_increment.size(), vectors, "fluid velocity increment");
  require_size(result.solid_velocity_increment.size(), vectors, "solid velocity increment");
  require_size(result.fluid_impulse.size(), vectors, "fluid impulse");
  require_size(result.solid_impulse.size(), vectors, "solid impulse");
  if (!result.drag_coefficient.empty()) {
    require_size(result.drag_coefficient.size(), cells, "drag coefficient");
  }

  const auto d = static_cast<std::size_t>(dim);
  for (std::size_t cell = 0; cell < cells; ++cell) {
    const double rho_f = fluid.bulk_density[cell];
    const double rho_s = solid.bulk_density[cell];
    require_valid(rho_f >= 0 && std::isfinite(rho_f), cell, "fluid bulk density", rho_f);
    require_valid(rho_s >= 0 && std::isfinite(rho_s), cell, "solid bulk density", rho_s);
    // A full cell's fraction mapped between two grids may exceed 1 by round-off.
    const double mapped_phi_s = medium.solid_fraction[cell];
    require_valid(mapped_phi_s >= 0 && mapped_phi_s <= 1.0 + 1e-12, cell, "solid fraction",
                  mapped_phi_s);
    const double phi_s = std::min(mapped_phi_s, 1.0);
    const double* u_f = fluid.velocity.data() + cell * d;
    const double* u_s = solid.velocity.data() + cell * d;
    double relative_speed_squared = 0;
    for (std::size_t k = 0; k < d; ++k) {
      require_valid(std::isfinite(u_f[k]), cell, "a fluid velocity component", u_f[k]);
      require_valid(std::isfinite(u_s[k]), cell, "a solid velocity component", u_s[k]);
      relative_speed_squared += (u_s[k] - u_f[k]) * (u_s[k] - u_f[k]);
    }

    double drag = 0;
    if (rho_f > 0 && rho_s > 0) {
      DragInput input;
      input.solid_fraction = phi_s;
      input.fluid_density = phi_s < 1 ? rho_f / (1.0 - phi_s) : 0.0;
      input.relative_speed = std::sqrt(relative_speed_squared);
      if (law.cell_input() == CellInput::grain_size) input.grain_size = medium.grain_size[cell];
      if (law.cell_input() == CellInput::permeability) {
        input.permeability = medium.permeability[cell];
      }
      drag = law.coefficient(input);
      require_valid(drag >= 0, cell, "the drag coefficient", drag);
    }
    if (!result.drag_coefficient.empty()) result.drag_coefficient[cell] = drag;

    for (std::size_t k = 0; k < d; ++k) {
      const std::size_t at = cell * d + k;
      // Tran et al., MPMICE, eq. 131 in closed form; drag = +inf ties the phases.
      const double impulse = two_material_impulse(rho_f, rho_s, u_f[k], u_s[k], dt * drag);
      result.fluid_velocity_increment[at] = rho_f > 0 ? impulse / rho_f : 0.0;
      result.solid_velocity_increment[at] = rho_s > 0 ? -impulse / rho_s : 0.0;
      result.fluid_impulse[at] = impulse * cell_volume[cell];
      result.solid_impulse[at] = -impulse * cell_volume[cell];
    }
  }
}

}  // namespace cosim::exchange

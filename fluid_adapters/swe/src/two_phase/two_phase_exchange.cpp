#include "swe/two_phase/two_phase_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "cosim/error.hpp"

namespace swe {

TwoPhaseExchange::TwoPhaseExchange(const Solver& solver, TwoPhaseParameters parameters,
                                   UniformSources sources, SolidLayer layer,
                                   std::vector<double> base_bed)
    : parameters_(parameters), sources_(sources), cells_(solver.cell_count()) {
  if (solver.dimension() != 2)
    throw cosim::InputError("two-phase shallow water: needs a 2D solver (uniform cells)");
  cell_area_ = solver.cell_size(0);
  fluid_density_ = solver.physics().density;
  dry_depth_ = solver.physics().dry_depth;
  parameters_.drag.gravity = solver.physics().gravity;
  try {
    cosim::exchange::check(parameters_.drag);
  } catch (const std::invalid_argument& e) {
    throw cosim::InputError(fmt::format("two-phase drag: {}", e.what()));
  }
  if (!(parameters_.solid_density > fluid_density_) || !std::isfinite(parameters_.solid_density))
    throw cosim::InputError(
        fmt::format("two-phase shallow water: the grain density {} kg/m^3 must exceed the "
                    "fluid's {} kg/m^3",
                    parameters_.solid_density, fluid_density_));
  if (!(parameters_.fluid_viscosity > 0.0) || !std::isfinite(parameters_.fluid_viscosity))
    throw cosim::InputError(
        fmt::format("two-phase shallow water: the fluid viscosity {} Pa s must be positive",
                    parameters_.fluid_viscosity));
  for (double rate : {sources_.rain_rate, sources_.infiltration_rate})
    if (!(rate >= 0.0) || !std::isfinite(rate))
      throw cosim::InputError(fmt::format(
          "two-phase shallow water: rain and infiltration rates must be finite and >= 0, got {} "
          "m/s",
          rate));
  set_layer(std::move(layer));
  set_base_bed(base_bed);
  impulse_x_.assign(cells_, 0.0);
  impulse_y_.assign(cells_, 0.0);
}

void TwoPhaseExchange::set_layer(SolidLayer layer) {
  validate(layer, cells_);
  layer_ = std::move(layer);
}

void TwoPhaseExchange::set_base_bed(std::span<const double> base_bed) {
  if (base_bed.size() != cells_)
    throw cosim::InputError(fmt::format(
        "two-phase shallow water: the bed has {} values for {} cells", base_bed.size(), cells_));
  base_bed_.assign(base_bed.begin(), base_bed.end());
}

void TwoPhaseExchange::apply_bed(Solver& solver) const {
  std::vector<double> bed(cells_);
  for (std::size_t c = 0; c < cells_; ++c) bed[c] = base_bed_[c] + layer_.depth[c];
  solver.set_bed(bed);
}

SourceVolumes TwoPhaseExchange::after_step(Solver& solver, double dt) {
  if (solver.cell_count() != cells_)
    throw cosim::InputError("two-phase shallow water: the solver is not the exchange's");
  const auto h = solver.depth(), hu = solver.discharge_x(), hv = solver.discharge_y();
  h_.assign(h.begin(), h.end());
  hu_.assign(hu.begin(), hu.end());
  hv_.assign(hv.begin(), hv.end());
  const SourceVolumes volumes = add_sources(sources_, layer_, cell_area_, dt, h_, hu_, hv_);
  exchange_momentum(parameters_, fluid_density_, dry_depth_, cell_area_, dt, h_, hu_, hv_, layer_,
                    impulse_x_, impulse_y_);
  solver.set_state(h_, hu_, hv_);
  volume_added_ += volumes.added;
  volume_infiltrated_ += volumes.infiltrated;
  return volumes;
}

void TwoPhaseExchange::clear_impulse() {
  std::fill(impulse_x_.begin(), impulse_x_.end(), 0.0);
  std::fill(impulse_y_.begin(), impulse_y_.end(), 0.0);
}

TwoPhaseExchange::State TwoPhaseExchange::state() const {
  return {layer_.velocity_x, layer_.velocity_y, impulse_x_,
          impulse_y_,        volume_added_,     volume_infiltrated_};
}

void TwoPhaseExchange::set_state(const State& state) {
  for (const std::vector<double>* values :
       {&state.velocity_x, &state.velocity_y, &state.impulse_x, &state.impulse_y}) {
    if (values->size() != cells_)
      throw cosim::InputError(fmt::format(
          "two-phase shallow water: a state of {} values for {} cells", values->size(), cells_));
    for (double v : *values)
      if (!std::isfinite(v))
        throw cosim::InputError("two-phase shallow water: a state with non-finite values");
  }
  layer_.velocity_x = state.velocity_x;
  layer_.velocity_y = state.velocity_y;
  impulse_x_ = state.impulse_x;
  impulse_y_ = state.impulse_y;
  volume_added_ = state.added;
  volume_infiltrated_ = state.infiltrated;
}

void TwoPhaseExchange::save_state() {
  saved_ = state();
  has_saved_ = true;
}

void TwoPhaseExchange::restore_state() {
  if (!has_saved_)
    throw cosim::Error(cosim::ExitCode::internal_error,
                       "two-phase shallow water: no saved state to restore");
  set_state(saved_);
}

}  // namespace swe

#pragma once

#include <span>
#include <vector>

#include "swe/solver.hpp"
#include "swe/two_phase/fluid_sources.hpp"
#include "swe/two_phase/phase_drag.hpp"
#include "swe/two_phase/solid_layer.hpp"

namespace swe {

// The two-phase mode of the 2D shallow water (van den Bout et al., OpenLISEM
// Hazard, eqs. 47-65 with the solids' own balances in the particles'
// process): the free fluid flows over bed + h_s, and after each fluid step
// (operator splitting)
//
//   exchange.apply_bed(solver);               // when the layer or the bed changed
//   solver.step(dt);
//   exchange.after_step(solver, dt);
//
// adds its sources (released fluid, rain, infiltration; add_sources) and
// relaxes the solids' and the fluid's velocities against each other
// (exchange_momentum), the fluid holding the solids' velocity between
// windows. Manning friction stays the solver's (on the fluid's depth h_f).
// Momentum in kg m/s; the impulse accumulated is the one the solids receive.
class TwoPhaseExchange {
 public:
  // `base_bed` is the ground without solids, one value per cell of `solver`
  // (a 2D solver). Throws cosim::InputError for a 1D solver, a layer that
  // fails validate(), a bed of another size, out-of-range drag parameters
  // (check() in generalised_drag.hpp) or a negative rain or infiltration rate.
  TwoPhaseExchange(const Solver& solver, TwoPhaseParameters parameters, UniformSources sources,
                   SolidLayer layer, std::vector<double> base_bed);

  // A new layer (from the coupler, each window) or ground; then apply_bed().
  void set_layer(SolidLayer layer);
  void set_base_bed(std::span<const double> base_bed);
  // The solver's bed becomes base bed + h_s, through Solver::set_bed, which
  // keeps the fluid's depths: the free surface rises with the solids.
  void apply_bed(Solver& solver) const;

  // Sources, then the drag, over the step dt the solver has just made.
  // Returns the step's source volumes [m^3].
  SourceVolumes after_step(Solver& solver, double dt);

  const SolidLayer& layer() const { return layer_; }
  const std::vector<double>& base_bed() const { return base_bed_; }
  const TwoPhaseParameters& parameters() const { return parameters_; }
  // Impulse the solids received per cell since the last clear_impulse() [kg m/s].
  const std::vector<double>& impulse_x() const { return impulse_x_; }
  const std::vector<double>& impulse_y() const { return impulse_y_; }
  void clear_impulse();
  // Totals since construction [m^3].
  double volume_added() const { return volume_added_; }
  double volume_infiltrated() const { return volume_infiltrated_; }

  // What the exchange adds to the fluid's state: the layer's velocity, the
  // impulses and the source totals.
  struct State {
    std::vector<double> velocity_x, velocity_y, impulse_x, impulse_y;
    double added = 0.0, infiltrated = 0.0;
  };
  State state() const;
  // Throws cosim::InputError for arrays of another size or non-finite values.
  void set_state(const State& state);
  // A copy of state(), put back by restore_state() (a window that runs again).
  void save_state();
  void restore_state();

 private:
  TwoPhaseParameters parameters_;
  UniformSources sources_;
  SolidLayer layer_;
  std::vector<double> base_bed_;
  std::size_t cells_ = 0;
  double cell_area_ = 0.0;
  double fluid_density_ = 0.0, dry_depth_ = 0.0;
  std::vector<double> impulse_x_, impulse_y_;
  std::vector<double> h_, hu_, hv_;
  double volume_added_ = 0.0, volume_infiltrated_ = 0.0;
  State saved_;
  bool has_saved_ = false;
};

}  // namespace swe

#pragma once

#include <cstddef>
#include <vector>

#include "mpm/particles/particles.hpp"

namespace mpm {

template <int Dim>
class Solver;

// Work and heat a run accumulates from its start [J] (per unit depth in 2D);
// Totals reports them.
struct AccumulatedEnergy {
  double contact_dissipation = 0.0;
  double boundary_dissipation = 0.0;
  double external_work = 0.0;
  double internal_work = 0.0;
  double external_heat = 0.0;
  double heat_through_faces = 0.0;
};

// A copy of everything the steps of a Solver<Dim> carry from one step to the
// next: restored, the steps that follow repeat bit for bit (implicit
// coupling runs a window again from its start, architecture.md §13). That
// is the particles (every attribute, material state included), the motion
// of the rigid bodies, the time, the step count and the accumulated energy.
// The grid carries nothing (each step rebuilds it from the particles), nor
// do the materials (immutable) or the time step (computed afresh from the
// particles each step).
//
// Saved into again, the arrays keep their capacity: after the first save,
// saving and restoring allocate nothing.
template <int Dim>
class SolverState {
 public:
  bool is_saved() const { return saved_; }
  // Bytes held (capacity included).
  double bytes() const;

 private:
  friend class Solver<Dim>;

  bool saved_ = false;
  Particles<Dim> particles_;
  std::vector<Vec<Dim>> rigid_velocity_;   // per body
  std::vector<Vec<Dim>> contact_impulse_;  // per body, of the last step
  double time_ = 0.0;
  std::size_t steps_ = 0;
  AccumulatedEnergy accumulated_;
};

template <int Dim>
double SolverState<Dim>::bytes() const {
  const double bodies = static_cast<double>(
      (rigid_velocity_.capacity() + contact_impulse_.capacity()) * sizeof(Vec<Dim>));
  return particles_.bytes_per_particle() * static_cast<double>(particles_.size()) + bodies;
}

}  // namespace mpm

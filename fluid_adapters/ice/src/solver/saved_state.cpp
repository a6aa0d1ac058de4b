#include "ice/solver/saved_state.hpp"

#include "ice/solver/ice_solver.hpp"

namespace ice {

// Plain assignments: a vector assigned one of the same size keeps its
// storage, so from the second window on nothing is allocated.
template <int Dim>
void IceSolver<Dim>::save_state(SavedIceState<Dim>& saved) const {
  saved.fluid = state_;
  saved.time = time_;
  saved.steps = steps_;
  saved.kappa = kappa_;
  saved.mixture_kappa = mixture_kappa_;
  saved.pressure_increment = pressure_increment_;
  saved.last_face_rate = last_face_rate_;
  saved.face_velocity = face_velocity_;
  saved.face_pressure = face_pressure_;
  saved.solid_drag_on = solid_drag_on_;
  saved.solid_drag = solid_drag_;
  saved.solid_bulk_density = solid_bulk_density_;
  saved.solid_exchange_velocity = solid_exchange_velocity_;
  saved.solid_impulse = solid_impulse_;
  saved.previous_face_velocity = previous_face_velocity_;
  saved.porosity_to_displace = porosity_to_displace_;
}

template <int Dim>
void IceSolver<Dim>::restore_state(const SavedIceState<Dim>& saved) {
  state_ = saved.fluid;
  time_ = saved.time;
  steps_ = saved.steps;
  kappa_ = saved.kappa;
  mixture_kappa_ = saved.mixture_kappa;
  pressure_increment_ = saved.pressure_increment;
  last_face_rate_ = saved.last_face_rate;
  face_velocity_ = saved.face_velocity;
  face_pressure_ = saved.face_pressure;
  solid_drag_on_ = saved.solid_drag_on;
  solid_drag_ = saved.solid_drag;
  solid_bulk_density_ = saved.solid_bulk_density;
  solid_exchange_velocity_ = saved.solid_exchange_velocity;
  solid_impulse_ = saved.solid_impulse;
  previous_face_velocity_ = saved.previous_face_velocity;
  porosity_to_displace_ = saved.porosity_to_displace;
}

template void IceSolver<1>::save_state(SavedIceState<1>&) const;
template void IceSolver<1>::restore_state(const SavedIceState<1>&);
template void IceSolver<2>::save_state(SavedIceState<2>&) const;
template void IceSolver<2>::restore_state(const SavedIceState<2>&);
template void IceSolver<3>::save_state(SavedIceState<3>&) const;
template void IceSolver<3>::restore_state(const SavedIceState<3>&);

}  // namespace ice

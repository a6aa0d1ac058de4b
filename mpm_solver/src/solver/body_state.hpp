#pragma once

#include <cstddef>
#include <string>

#include "mpm/case/case_description.hpp"
#include "mpm/material/material.hpp"

namespace mpm::detail {

// What the solver keeps of a body while it runs.
template <int Dim>
struct BodyState {
  std::string name;
  std::size_t first = 0;  // particles first .. first + count - 1
  std::size_t count = 0;
  const Material* material = nullptr;  // null for rigid bodies
  const RigidMotion* rigid = nullptr;  // null for deformable bodies
  int field = 0;                       // grid velocity field
  double p_wave_modulus = 0.0;         // K + 4G/3 of the material, for the time step [Pa]
  double mass = 0.0;
  Vec<Dim> rigid_velocity = Vec<Dim>::Zero();
  Vec<Dim> contact_impulse = Vec<Dim>::Zero();  // on a rigid body, this step [N s]

  bool is_rigid() const { return rigid != nullptr; }
};

}  // namespace mpm::detail

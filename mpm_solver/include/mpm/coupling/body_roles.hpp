#pragma once

#include <cstdint>
#include <vector>

#include "mpm/case/case_description.hpp"
#include "mpm/coupling/coupling_spec.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"

namespace mpm::coupling {

// What each body is to the coupling, by body index.
struct BodyRole {
  bool rigid = false;   // moves as the case prescribes: takes no coupling force
  bool porous = false;  // has a pore pressure (effective stress principle)
  bool held = false;    // immovable for the momentum exchange (rigid, or listed in held_bodies)
  bool bed = true;      // forms the bed for the shallow-water pairing
};

// Resolves held_bodies and bed_bodies by name; an unknown name is an
// InputError listing the bodies.
std::vector<BodyRole> body_roles(const CaseDescription& description, const CouplingSpec& spec);

// Particles whose solid cannot take the exchange impulse: those of held
// bodies and, with `at_fixed_faces`, those in the MPM cells along a fixed
// grid face (their grid values are pinned). 1 = held.
template <int Dim>
std::vector<std::uint8_t> held_particles(const Particles<Dim>& particles, const Grid<Dim>& grid,
                                         const std::vector<BodyRole>& roles,
                                         const FaceConditions& faces, bool at_fixed_faces);

}  // namespace mpm::coupling

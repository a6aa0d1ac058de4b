#pragma once

namespace swe {

// One side of a face in the face's frame: depth, velocity normal to the face
// (positive from left to right) and tangential velocity (zero in 1D).
struct FaceState {
  double h = 0.0;
  double un = 0.0;
  double ut = 0.0;
};

// Flux through a face per unit face length, in the face's frame.
struct FaceFlux {
  double mass = 0.0;                 // h u_n                 [m^2/s]
  double normal_momentum = 0.0;      // h u_n^2 + g h^2 / 2   [m^3/s^2]
  double tangential_momentum = 0.0;  // h u_n u_t             [m^3/s^2]
};

// The exact flux F(U) of one state (Zheng et al., eq. 24).
inline FaceFlux physical_flux(const FaceState& s, double g) {
  const double q = s.h * s.un;
  return {q, q * s.un + 0.5 * g * s.h * s.h, q * s.ut};
}

}  // namespace swe

#pragma once

#include <array>
#include <optional>

#include "cosim/mesh.hpp"
#include "swe/two_phase/fluid_sources.hpp"
#include "swe/two_phase/phase_drag.hpp"
#include "swe/two_phase/solid_layer.hpp"

namespace swe {

// A static solid layer a standalone case lays at the start: uniform over a
// box (or everywhere).
struct InitialSolidLayer {
  bool in_box = false;
  std::array<double, 2> min{0.0, 0.0}, max{0.0, 0.0};
  double depth = 0.0;                        // h_s [m]
  double density = 0.0;                      // rho_c [kg/m^3]
  double structured_share = 0.0;             // f_sc [-]
  std::array<double, 2> velocity{0.0, 0.0};  // [m/s]
};

// The `two_phase` block of a swe_case.
struct TwoPhaseSpec {
  TwoPhaseParameters parameters;
  UniformSources sources;
  std::optional<InitialSolidLayer> initial_layer;
};

// The layer the spec lays on `cells` (a 2D grid's cells): the initial layer
// inside its box, no solids elsewhere (density rho_s there); no solids at all
// without an initial layer.
SolidLayer lay_solid_layer(const TwoPhaseSpec& spec, const cosim::Mesh& cells);

}  // namespace swe

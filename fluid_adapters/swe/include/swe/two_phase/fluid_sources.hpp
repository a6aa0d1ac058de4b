#pragma once

#include <span>

#include "swe/two_phase/solid_layer.hpp"

namespace swe {

// Uniform rain and infiltration [m/s] (van den Bout et al., OpenLISEM
// Hazard, eqs. 47 and 49: R - I).
struct UniformSources {
  double rain_rate = 0.0;          // R, >= 0
  double infiltration_rate = 0.0;  // I, >= 0
};

// Water volumes a step added and took [m^3 (2D), m^2 (1D)].
struct SourceVolumes {
  double added = 0.0;        // rain and released fluid
  double infiltrated = 0.0;  // taken by infiltration
};

// The fluid's sources over dt, per cell: the fluid the solids release
// (layer.released_fluid_rate dt / |cell|, carrying the solids' velocity, so
// it brings its momentum to the fluid; the particles lose it with the mass)
// and rain (R dt, without horizontal momentum) are added first, then
// infiltration takes min(I dt, the water then present), the water leaving
// with its cell's velocity. Depths stay non-negative by construction: a
// cell loses at most what it holds, and what it loses is what is counted, so
// the volume after is the volume before + added - infiltrated to round-off.
// Throws cosim::InputError for negative or non-finite rates or dt.
SourceVolumes add_sources(const UniformSources& sources, const SolidLayer& layer, double cell_area,
                          double dt, std::span<double> h, std::span<double> hu,
                          std::span<double> hv);

}  // namespace swe

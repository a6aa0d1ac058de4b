#include "swe/two_phase/two_phase_spec.hpp"

namespace swe {

SolidLayer lay_solid_layer(const TwoPhaseSpec& spec, const cosim::Mesh& cells) {
  const std::size_t n = cells.size();
  const std::optional<InitialSolidLayer>& initial = spec.initial_layer;
  SolidLayer layer =
      empty_solid_layer(n, initial ? initial->density : spec.parameters.solid_density);
  if (!initial) return layer;
  for (std::size_t c = 0; c < n; ++c) {
    const cosim::Vec3 x = cells.position(c);
    if (initial->in_box && (x[0] < initial->min[0] || x[0] > initial->max[0] ||
                            x[1] < initial->min[1] || x[1] > initial->max[1]))
      continue;
    layer.depth[c] = initial->depth;
    layer.velocity_x[c] = initial->velocity[0];
    layer.velocity_y[c] = initial->velocity[1];
    layer.structured_share[c] = initial->structured_share;
  }
  return layer;
}

}  // namespace swe

#pragma once

#include <cstddef>
#include <vector>

#include "mpm/core/tensor.hpp"

namespace mpm {

// Particles of one body as seeded: initial positions, volumes and domain
// half-lengths per direction (for uGIMP) [m].
template <int Dim>
struct SeededParticles {
  std::vector<Vec<Dim>> positions;
  std::vector<double> volumes;
  std::vector<Vec<Dim>> half_lengths;

  std::size_t size() const { return positions.size(); }
  double total_volume() const {
    double v = 0.0;
    for (double x : volumes) v += x;
    return v;
  }
};

}  // namespace mpm

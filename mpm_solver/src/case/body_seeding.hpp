#pragma once

#include <array>
#include <functional>
#include <vector>

#include "cosim/config/node.hpp"
#include "mpm/case/case_description.hpp"

// Fills a body's `geometry` with particles (the loader's side of the
// geometry module).
namespace mpm::case_loading {

enum class Seeding { regular, r2 };

struct SeededBody {
  std::vector<Vec3d> positions;
  std::vector<double> volumes;      // [m^3], per unit depth in 2D [m^2]
  std::vector<Vec3d> half_lengths;  // [m]
};

// Called with the particles a body is estimated to get (from its region's
// volume, or the count a points file lists) before they are seeded; throws
// to refuse a body too large to seed.
using BeforeSeeding = std::function<void(double estimated_particles)>;

// `geometry` is the validated `bodies[i].geometry` mapping with exactly one
// key; `particles_per_cell` counts per direction.
SeededBody seed_body(const cosim::config::Node& geometry, int dimension, const GridSpec& grid,
                     const std::array<int, 3>& particles_per_cell, Seeding seeding,
                     const BeforeSeeding& before_seeding);

}  // namespace mpm::case_loading

#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "mpm/case/case_description.hpp"
#include "mpm/grid/grid.hpp"

namespace mpm::detail {

// Applies the face conditions to the grid values on the faces (the first and
// last value of every kernel lie on the faces), on every deformable field's
// updated velocity. Fixed: v = 0. Slip: no normal velocity. Frictional: no
// velocity into the wall, and the tangential velocity reduced by mu times
// the normal velocity removed (Coulomb). Returns the kinetic energy removed
// by friction [J].
using FaceValues = std::array<std::vector<std::size_t>, 6>;

// The owned grid values (stored indices) on each face, x-, x+, y-, y+, z-, z+.
template <int Dim>
FaceValues face_values(const Grid<Dim>& grid) {
  FaceValues faces;
  for (std::size_t v = grid.owned_begin(); v < grid.owned_end(); ++v) {
    const auto index = grid.unflat(grid.flat_of_stored(v));
    for (int d = 0; d < Dim; ++d) {
      if (index[d] == 0) faces[static_cast<std::size_t>(2 * d)].push_back(v);
      if (index[d] == grid.dofs[d] - 1) faces[static_cast<std::size_t>(2 * d + 1)].push_back(v);
    }
  }
  return faces;
}

template <int Dim>
double apply_face_conditions(const FaceConditions& faces, const FaceValues& values,
                             const std::vector<bool>& rigid_field, Grid<Dim>& grid) {
  double dissipated = 0.0;
  const std::size_t n = grid.size();
  for (int d = 0; d < Dim; ++d) {
    for (int side = 0; side < 2; ++side) {
      const FaceCondition& face = faces[static_cast<std::size_t>(2 * d + side)];
      if (face.kind == FaceCondition::Kind::free) continue;
      const double outward = side == 0 ? -1.0 : 1.0;
      for (const std::size_t v : values[static_cast<std::size_t>(2 * d + side)]) {
        for (int f = 0; f < grid.fields; ++f) {
          if (rigid_field[static_cast<std::size_t>(f)]) continue;
          const std::size_t i = static_cast<std::size_t>(f) * n + v;
          Vec<Dim>& vel = grid.velocity[i];
          switch (face.kind) {
            case FaceCondition::Kind::fixed:
              vel.setZero();
              break;
            case FaceCondition::Kind::slip:
              vel[d] = 0.0;
              break;
            case FaceCondition::Kind::frictional: {
              const double into_wall = vel[d] * outward;
              if (into_wall <= 0.0) break;
              const Vec<Dim> before = vel;
              vel[d] = 0.0;
              const double tangential = vel.norm();
              if (tangential > 0.0)
                vel *= std::max(0.0, 1.0 - face.friction * into_wall / tangential);
              const Vec<Dim> tangent_before = before - before[d] * Vec<Dim>::Unit(d);
              dissipated += 0.5 * grid.mass[i] * (tangent_before.squaredNorm() - vel.squaredNorm());
              break;
            }
            case FaceCondition::Kind::free:
              break;
          }
        }
      }
    }
  }
  return dissipated;
}

}  // namespace mpm::detail

#pragma once

#include <cstddef>
#include <vector>

#include "mpm/grid/grid.hpp"

namespace mpm::detail {

// Velocity fields of the grid and how they meet.
struct ContactFields {
  std::vector<bool> rigid;                    // per field
  std::vector<std::vector<double>> friction;  // per field pair
};

struct ContactResult {
  double dissipated = 0.0;  // work of the friction forces [J]
};

// Frictional multi-body contact on the grid (Bardenhagen et al. 2001, as in
// Tran et al., MPMICE, eqs. 20-22). At a grid value where several fields
// have mass, each deformable field b is compared with the centre-of-mass
// velocity v_cm (the rigid velocity when a rigid field is present, its mass
// being taken as infinite). Along the contact normal n_b (from b towards the
// others, from the fields' mass gradients), the field approaches when
// (v_b - v_cm) . n_b > 0; then the normal part is removed and the
// tangential part is reduced by mu times it (eq. 20), or removed entirely
// when friction is enough to stick (eq. 21). Between two deformable fields
// the normals are opposite and the corrections conserve momentum exactly.
// The friction force times the sliding distance is the dissipated work
// (eq. 22). Runs on the owned values. `impulse_on_field` receives, per
// slab of values (`slab_of_value`) and field (slab-major), the momentum the
// others lost to the field: the reaction on rigid bodies, summed per slab so
// that its total has the same bits on any number of ranks.
template <int Dim, class SlabOfValue>
ContactResult apply_grid_contact(const ContactFields& fields, Grid<Dim>& grid,
                                 SlabOfValue&& slab_of_value,
                                 std::vector<Vec<Dim>>& impulse_on_field) {
  ContactResult result;
  const std::size_t n = grid.size();
  const int F = grid.fields;
  std::fill(impulse_on_field.begin(), impulse_on_field.end(), Vec<Dim>::Zero());
  constexpr double tiny = 1e-300;
  for (std::size_t v = grid.owned_begin(); v < grid.owned_end(); ++v) {
    int present = 0;
    int rigid_field = -1;
    double mass = 0.0;
    Vec<Dim> momentum = Vec<Dim>::Zero();
    Vec<Dim> gradient_sum = Vec<Dim>::Zero();
    int heaviest = -1;
    for (int f = 0; f < F; ++f) {
      const std::size_t i = static_cast<std::size_t>(f) * n + v;
      if (grid.mass[i] <= tiny) continue;
      ++present;
      gradient_sum += grid.mass_gradient[i];
      if (fields.rigid[static_cast<std::size_t>(f)]) {
        rigid_field = f;
      } else {
        mass += grid.mass[i];
        momentum += grid.mass[i] * grid.velocity[i];
      }
    }
    if (present < 2) continue;
    Vec<Dim> v_cm = rigid_field >= 0 ? grid.velocity[static_cast<std::size_t>(rigid_field) * n + v]
                                     : Vec<Dim>(momentum / mass);
    for (int b = 0; b < F; ++b) {
      const std::size_t i = static_cast<std::size_t>(b) * n + v;
      if (grid.mass[i] <= tiny || fields.rigid[static_cast<std::size_t>(b)]) continue;
      // The partner that sets the friction: the rigid field, else the heaviest other.
      int partner = rigid_field;
      if (partner < 0) {
        double heaviest_mass = 0.0;
        for (int c = 0; c < F; ++c) {
          const std::size_t j = static_cast<std::size_t>(c) * n + v;
          if (c != b && grid.mass[j] > heaviest_mass) {
            heaviest_mass = grid.mass[j];
            heaviest = c;
          }
        }
        partner = heaviest;
      }
      if (partner < 0) continue;
      // sum_p m_p grad N_i(x_p) points out of a body; the normal from b
      // towards the others is b's outward direction minus theirs.
      const Vec<Dim> others = gradient_sum - grid.mass_gradient[i];
      Vec<Dim> normal = grid.mass_gradient[i] - others;
      const double length = normal.norm();
      if (!(length > 0.0)) continue;
      normal /= length;
      const Vec<Dim> relative = grid.velocity[i] - v_cm;
      const double approach = relative.dot(normal);
      if (approach <= 0.0) continue;
      const Vec<Dim> tangential = relative - approach * normal;
      const double slip = tangential.norm();
      const double mu =
          fields.friction[static_cast<std::size_t>(b)][static_cast<std::size_t>(partner)];
      Vec<Dim> corrected;
      if (slip <= mu * approach) {
        corrected = Vec<Dim>::Zero();  // sticks
      } else {
        corrected = tangential * (1.0 - mu * approach / slip);
      }
      const double m = grid.mass[i];
      // Eq. 22: friction force m mu approach / dt times the sliding distance |corrected| dt.
      if (slip > mu * approach) result.dissipated += m * mu * approach * corrected.norm();
      const Vec<Dim> change = corrected - relative;
      grid.velocity[i] += change;
      impulse_on_field[slab_of_value(v) * static_cast<std::size_t>(F) +
                       static_cast<std::size_t>(partner)] -= m * change;
    }
  }
  return result;
}

}  // namespace mpm::detail

#include "ice/advection/advector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"

namespace ice {

namespace {

std::size_t size_of(int count) {
  return static_cast<std::size_t>(count);
}

// The buffers along another direction d than x: two cell rows of
// differences and two face rows of fluxes (stride(d) values each).
template <int Dim>
std::size_t plane_buffer_size(const CellGrid<Dim>& grid) {
  int largest = 0;
  for (int d = 1; d < Dim; ++d) largest = std::max(largest, 2 * grid.stride(d));
  return size_of(largest);
}

// The donor's profile at the centroid of the slab leaving through a face of
// Courant number nu, between the lower cell (value, limited difference) and
// the upper one; both candidates computed, so the choice is a select.
inline double face_flux(double nu, double lower, double lower_difference, double upper,
                        double upper_difference) {
  const double from_lower = lower + 0.5 * (1.0 - nu) * lower_difference;
  const double from_upper = upper - 0.5 * (1.0 + nu) * upper_difference;
  return nu * (nu >= 0.0 ? from_lower : from_upper);
}

// The same in a porous medium: the profile is the donor's value per unit of
// its pore space, q / n, and the slab carries it in the donor's pores.
inline double pore_face_flux(double nu, double lower, double lower_difference, double lower_pores,
                             double upper, double upper_difference, double upper_pores) {
  return (nu >= 0.0 ? lower_pores : upper_pores) *
         face_flux(nu, lower, lower_difference, upper, upper_difference);
}

// One face's flux from the profile values (q, or q / n with `pores`).
inline double donor_flux(const double* pores, int lower_cell, int upper_cell, double nu,
                         double lower, double lower_difference, double upper,
                         double upper_difference) {
  if (pores == nullptr) return face_flux(nu, lower, lower_difference, upper, upper_difference);
  return pore_face_flux(nu, lower, lower_difference, pores[lower_cell], upper, upper_difference,
                        pores[upper_cell]);
}

}  // namespace

template <int Dim>
Advector<Dim>::Advector(const CellGrid<Dim>& grid, Limiter limiter)
    : grid_(grid),
      limiter_(limiter),
      courant_(make_face_field(grid)),
      row_difference_(size_of(grid.cells()[0]), 0.0),
      row_flux_(size_of(grid.cells()[0] + 1), 0.0),
      difference_(plane_buffer_size(grid), 0.0),
      flux_(plane_buffer_size(grid), 0.0),
      change_(size_of(grid.cell_count()), 0.0),
      per_pore_volume_(size_of(grid.cell_count()), 0.0) {}

template <int Dim>
void Advector<Dim>::advance(const FaceField<Dim>& face_velocity, double dt,
                            std::span<const std::span<double>> fields) {
  advance(face_velocity, dt, fields, {});
}

template <int Dim>
void Advector<Dim>::advance(const FaceField<Dim>& face_velocity, double dt,
                            std::span<const std::span<double>> fields,
                            std::span<const double> porosity) {
  if (!porosity.empty() && porosity.size() != size_of(grid_.cell_count())) {
    throw std::invalid_argument("Advector: " + std::to_string(porosity.size()) +
                                " porosities for " + std::to_string(grid_.cell_count()) + " cells");
  }
  for (const double n : porosity) {
    if (!(n > 0.0 && n <= 1.0)) {
      throw std::invalid_argument("Advector: a porosity must lie in (0, 1], got " +
                                  std::to_string(n));
    }
  }
  const bool porous =
      std::any_of(porosity.begin(), porosity.end(), [](double n) { return n < 1.0; });
  pores_ = porous ? porosity.data() : nullptr;
  if (!(dt >= 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("Advector: time step must be finite and non-negative, got " +
                                std::to_string(dt));
  }
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (fields[k].size() != size_of(grid_.cell_count())) {
      throw std::invalid_argument("Advector: field " + std::to_string(k) + " has " +
                                  std::to_string(fields[k].size()) + " values for " +
                                  std::to_string(grid_.cell_count()) + " cells");
    }
  }
  set_face_courant_numbers(face_velocity, dt);
  for (const std::span<double> field : fields) {
    profile_ = field.data();
    if (pores_ != nullptr) {
      for (std::size_t c = 0; c < field.size(); ++c) per_pore_volume_[c] = field[c] / pores_[c];
      profile_ = per_pore_volume_.data();
    }
    switch (limiter_) {
      case Limiter::first_order:
        advance_field<Limiter::first_order>(field);
        break;
      case Limiter::minmod:
        advance_field<Limiter::minmod>(field);
        break;
      case Limiter::van_leer:
        advance_field<Limiter::van_leer>(field);
        break;
    }
  }
}

template <int Dim>
void Advector<Dim>::set_face_courant_numbers(const FaceField<Dim>& face_velocity, double dt) {
  for (int d = 0; d < Dim; ++d) {
    const std::vector<double>& velocity = face_velocity[d];
    std::vector<double>& courant = courant_[d];
    if (velocity.size() != courant.size()) {
      throw std::invalid_argument("Advector: " + std::to_string(velocity.size()) +
                                  " face velocities normal to direction " + std::to_string(d) +
                                  " for " + std::to_string(courant.size()) + " faces");
    }
    const double dt_over_dx = dt / grid_.spacing()[d];
    bool out_of_range = false;
    for (std::size_t f = 0; f < courant.size(); ++f) {
      courant[f] = velocity[f] * dt_over_dx;
      out_of_range |= !(std::abs(courant[f]) <= 1.0);
    }
    if (out_of_range) {
      const auto face = std::find_if(courant.begin(), courant.end(),
                                     [](double nu) { return !(std::abs(nu) <= 1.0); });
      const auto f = static_cast<std::size_t>(face - courant.begin());
      throw cosim::NumericalError(
          "advection: face " + std::to_string(f) + " normal to direction " + std::to_string(d) +
          " has velocity " + std::to_string(velocity[f]) + " m/s, Courant number |U| dt/dx = " +
          std::to_string(std::abs(*face)) + " (must be <= 1; dt = " + std::to_string(dt) + " s)");
    }
  }
}

// One field: the fluxes of each direction in turn (the differences limited
// on the fly, row by row in small buffers), accumulated per cell as
// change_c += (flux_lower face - flux_upper face), then q += change. The
// last direction adds the change to a cell row as soon as it is complete:
// what is read later (the rows above) is still the old q. Each cell and face
// gets exactly the operations of the direction-by-direction form, in the
// same order (the first direction's change starts from 0 + ...).
template <int Dim>
template <Limiter limiter>
void Advector<Dim>::advance_field(std::span<double> q) {
  if constexpr (Dim == 1) {
    for (int row = 0; row < grid_.cell_count() / grid_.cells()[0]; ++row) {
      add_row_fluxes<limiter>(q, row, true);
    }
  } else {
    // Along y the rows along x are set as they are reached (one pass).
    add_plane_fluxes<limiter>(q, 1, Dim == 2);
    if constexpr (Dim == 3) add_plane_fluxes<limiter>(q, 2, true);
  }
}

// Along x (stride 1), row `row`: its limited differences, then its n + 1
// face fluxes (the end faces carry the end cells' values: zero-gradient
// ghosts, whose differences are zero too), then the cells' changes (the
// first direction: change = 0 + ...).
template <int Dim>
template <Limiter limiter>
void Advector<Dim>::add_row_fluxes(std::span<double> q, int row, bool last) {
  const int n = grid_.cells()[0];
  double* difference = row_difference_.data();
  double* flux = row_flux_.data();
  double* values = q.data() + row * n;
  const double* value = profile_ + row * n;
  const double* pores = pores_ == nullptr ? nullptr : pores_ + row * n;
  const double* courant = courant_[0].data() + row * (n + 1);
  difference[0] = 0.0;
  difference[n - 1] = 0.0;
  if constexpr (limiter != Limiter::first_order) {
    for (int i = 1; i < n - 1; ++i) {
      difference[i] = limited_difference<limiter>(value[i] - value[i - 1], value[i + 1] - value[i]);
    }
  } else {
    for (int i = 1; i < n - 1; ++i) difference[i] = 0.0;
  }
  flux[0] = courant[0] * values[0];
  for (int f = 1; f < n; ++f) {
    flux[f] = donor_flux(pores, f - 1, f, courant[f], value[f - 1], difference[f - 1], value[f],
                         difference[f]);
  }
  flux[n] = courant[n] * values[n - 1];
  double* cell_change = change_.data() + row * n;
  for (int i = 0; i < n; ++i) cell_change[i] = 0.0 + (flux[i] - flux[i + 1]);
  if (last) {
    for (int i = 0; i < n; ++i) values[i] += cell_change[i];
  }
}

// Along direction d > 0 (stride s): cells i s + inner of a row, for
// 0 <= inner < s, are contiguous, so the loops run over `inner` with the
// differences of the current and previous cell rows and the fluxes of the
// last face row in buffers of s values. Face row i lies between cell rows
// i - 1 and i; once its fluxes are known, cell row i - 1 is complete.
// Along y (d = 1, s = n_x) cell row i is one row along x, whose x fluxes
// are added first when the walk reaches it: it is complete along x before
// the y fluxes add to it, and q is read once.
template <int Dim>
template <Limiter limiter>
void Advector<Dim>::add_plane_fluxes(std::span<double> q, int direction, bool last) {
  const int s = grid_.stride(direction);
  const int n = grid_.cells()[direction];
  const int rows = grid_.cell_count() / (s * n);
  double* values = q.data();
  double* change = change_.data();
  double* previous_difference = difference_.data();
  double* current_difference = difference_.data() + s;
  double* previous_flux = flux_.data();
  double* current_flux = flux_.data() + s;
  for (int outer = 0; outer < rows; ++outer) {
    double* value = values + outer * s * n;  // cell i s + inner of this row
    const double* profile = profile_ + outer * s * n;
    const double* pores = pores_ == nullptr ? nullptr : pores_ + outer * s * n;
    double* cell_change = change + outer * s * n;
    const double* courant = courant_[direction].data() + outer * s * (n + 1);
    for (int inner = 0; inner < s; ++inner) previous_flux[inner] = courant[inner] * value[inner];
    for (int i = 0; i < n; ++i) {
      if (direction == 1) add_row_fluxes<limiter>(q, outer * n + i, false);
      // This cell row's limited differences (zero at the ends).
      const double* v = profile + i * s;
      if (limiter == Limiter::first_order || i == 0 || i == n - 1) {
        for (int inner = 0; inner < s; ++inner) current_difference[inner] = 0.0;
      } else {
        for (int inner = 0; inner < s; ++inner) {
          current_difference[inner] =
              limited_difference<limiter>(v[inner] - v[inner - s], v[inner + s] - v[inner]);
        }
      }
      if (i > 0) {
        // Face row i, then cell row i - 1 is complete.
        const double* nu = courant + i * s;
        const double* below = profile + (i - 1) * s;
        double* lower = value + (i - 1) * s;
        double* lower_change = cell_change + (i - 1) * s;
        if (pores == nullptr) {
          for (int inner = 0; inner < s; ++inner) {
            current_flux[inner] = face_flux(nu[inner], below[inner], previous_difference[inner],
                                            v[inner], current_difference[inner]);
          }
        } else {
          for (int inner = 0; inner < s; ++inner) {
            const int cell = i * s + inner;
            current_flux[inner] =
                pore_face_flux(nu[inner], below[inner], previous_difference[inner], pores[cell - s],
                               v[inner], current_difference[inner], pores[cell]);
          }
        }
        for (int inner = 0; inner < s; ++inner) {
          lower_change[inner] += previous_flux[inner] - current_flux[inner];
        }
        std::swap(previous_flux, current_flux);
        if (last) {
          for (int inner = 0; inner < s; ++inner) lower[inner] += lower_change[inner];
        }
      }
      std::swap(previous_difference, current_difference);
    }
    // The upper boundary face row carries the last cell row's values.
    const double* nu = courant + n * s;
    double* top = value + (n - 1) * s;
    double* top_change = cell_change + (n - 1) * s;
    for (int inner = 0; inner < s; ++inner) {
      top_change[inner] += previous_flux[inner] - nu[inner] * top[inner];
    }
    if (last) {
      for (int inner = 0; inner < s; ++inner) top[inner] += top_change[inner];
    }
  }
}

template class Advector<1>;
template class Advector<2>;
template class Advector<3>;

}  // namespace ice

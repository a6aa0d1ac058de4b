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

template <int Dim>
int largest_face_count(const CellGrid<Dim>& grid) {
  int largest = 0;
  for (int d = 0; d < Dim; ++d) {
    largest = std::max(largest, grid.face_count(d));
  }
  return largest;
}

}  // namespace

template <int Dim>
Advector<Dim>::Advector(const CellGrid<Dim>& grid, Limiter limiter)
    : grid_(grid),
      limiter_(limiter),
      courant_(make_face_field(grid)),
      difference_(size_of(grid.cell_count()), 0.0),
      flux_(size_of(largest_face_count(grid)), 0.0),
      change_(size_of(grid.cell_count()), 0.0) {}

template <int Dim>
void Advector<Dim>::advance(const FaceField<Dim>& face_velocity, double dt,
                            std::span<const std::span<double>> fields) {
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

template <int Dim>
template <Limiter limiter>
void Advector<Dim>::advance_field(std::span<double> q) {
  std::fill(change_.begin(), change_.end(), 0.0);
  for (int d = 0; d < Dim; ++d) {
    // first_order keeps the zero differences of construction.
    if constexpr (limiter != Limiter::first_order) {
      set_limited_differences<limiter>(q, d);
    }
    add_face_fluxes(q, d);
  }
  for (std::size_t c = 0; c < q.size(); ++c) {
    q[c] += change_[c];
  }
}

// Cells are visited as rows along `direction`: cell i of row `outer` at
// offset `inner` is outer s n + i s + inner (s = stride, n = cells along the
// direction), so the cells of a row, and those away from its ends, are
// contiguous ranges; each loop below runs over one such range.
template <int Dim>
template <Limiter limiter>
void Advector<Dim>::set_limited_differences(std::span<const double> q, int direction) {
  const int s = grid_.stride(direction);
  const int n = grid_.cells()[direction];
  const int rows = grid_.cell_count() / (s * n);
  const double* value = q.data();
  double* difference = difference_.data();
  for (int outer = 0; outer < rows; ++outer) {
    const int row = outer * s * n;
    // The zero-gradient ghosts make a boundary cell's difference zero.
    std::fill_n(difference + row, s, 0.0);
    std::fill_n(difference + row + (n - 1) * s, s, 0.0);
    for (int c = row + s; c < row + (n - 1) * s; ++c) {
      difference[c] = limited_difference<limiter>(value[c] - value[c - s], value[c + s] - value[c]);
    }
  }
}

// Face i of row `outer` is outer s (n + 1) + i s + inner, between cells i - 1
// and i of the row: face f of a row starting at cell `row` has the lower cell
// f - s (outer + 1) and the upper cell f - s outer. One flux per face, then
// each cell takes the difference of its two faces' fluxes, so what leaves
// one cell enters its neighbour exactly.
template <int Dim>
void Advector<Dim>::add_face_fluxes(std::span<const double> q, int direction) {
  const int s = grid_.stride(direction);
  const int n = grid_.cells()[direction];
  const int rows = grid_.cell_count() / (s * n);
  const double* value = q.data();
  const double* courant = courant_[direction].data();
  const double* difference = difference_.data();
  double* flux = flux_.data();
  double* change = change_.data();
  for (int outer = 0; outer < rows; ++outer) {
    const int face_row = outer * s * (n + 1);
    const int to_upper_cell = s * outer;
    const int to_lower_cell = to_upper_cell + s;
    // The boundary faces carry the boundary cell's value (zero-gradient ghost).
    for (int f = face_row; f < face_row + s; ++f) {
      flux[f] = courant[f] * value[f - to_upper_cell];
    }
    for (int f = face_row + s; f < face_row + n * s; ++f) {
      const int l = f - to_lower_cell;
      const int r = f - to_upper_cell;
      const double nu = courant[f];
      // The donor's profile at the centroid of the slab leaving through
      // the face; both candidates computed, so the choice is a select.
      const double from_lower = value[l] + 0.5 * (1.0 - nu) * difference[l];
      const double from_upper = value[r] - 0.5 * (1.0 + nu) * difference[r];
      flux[f] = nu * (nu >= 0.0 ? from_lower : from_upper);
    }
    for (int f = face_row + n * s; f < face_row + (n + 1) * s; ++f) {
      flux[f] = courant[f] * value[f - to_lower_cell];
    }
    const int row = outer * s * n;
    for (int c = row; c < row + n * s; ++c) {
      const int lower = c + to_upper_cell;
      change[c] += flux[lower] - flux[lower + s];
    }
  }
}

template class Advector<1>;
template class Advector<2>;
template class Advector<3>;

}  // namespace ice

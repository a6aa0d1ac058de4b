#include "ice/advection/advector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"

namespace ice {

namespace {

std::size_t size_of(int count) { return static_cast<std::size_t>(count); }

}  // namespace

template <int Dim>
Advector<Dim>::Advector(const CellGrid<Dim>& grid, Limiter limiter)
    : grid_(grid),
      limiter_(limiter),
      courant_(make_face_field(grid)),
      difference_(size_of(grid.cell_count()), 0.0),
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
    if constexpr (limiter == Limiter::first_order) {
      std::fill(difference_.begin(), difference_.end(), 0.0);
    } else {
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
// direction), so the innermost loop runs over contiguous memory.
template <int Dim>
template <Limiter limiter>
void Advector<Dim>::set_limited_differences(std::span<const double> q, int direction) {
  const int s = grid_.stride(direction);
  const int n = grid_.cells()[direction];
  const int rows = grid_.cell_count() / (s * n);
  double* difference = difference_.data();
  for (int outer = 0; outer < rows; ++outer) {
    const int row = outer * s * n;
    // The zero-gradient ghosts make a boundary cell's difference zero.
    std::fill_n(difference + row, s, 0.0);
    std::fill_n(difference + row + (n - 1) * s, s, 0.0);
    for (int i = 1; i < n - 1; ++i) {
      for (int c = row + i * s; c < row + (i + 1) * s; ++c) {
        difference[c] = limited_difference<limiter>(q[c] - q[c - s], q[c + s] - q[c]);
      }
    }
  }
}

// Faces are visited as rows too: face i of row `outer` is
// outer s (n + 1) + i s + inner, between cells i - 1 and i of the row.
template <int Dim>
void Advector<Dim>::add_face_fluxes(std::span<const double> q, int direction) {
  const int s = grid_.stride(direction);
  const int n = grid_.cells()[direction];
  const int rows = grid_.cell_count() / (s * n);
  const double* courant = courant_[direction].data();
  const double* difference = difference_.data();
  double* change = change_.data();
  for (int outer = 0; outer < rows; ++outer) {
    const int row = outer * s * n;
    const int face_row = outer * s * (n + 1);
    for (int inner = 0; inner < s; ++inner) {
      change[row + inner] += courant[face_row + inner] * q[row + inner];
    }
    for (int i = 1; i < n; ++i) {
      const int faces = face_row + i * s;
      const int lower = row + (i - 1) * s;
      for (int inner = 0; inner < s; ++inner) {
        const int l = lower + inner;
        const int r = l + s;
        const double nu = courant[faces + inner];
        // The donor's profile at the centroid of the slab leaving through the face.
        const double face_value = nu >= 0.0 ? q[l] + 0.5 * (1.0 - nu) * difference[l]
                                            : q[r] - 0.5 * (1.0 + nu) * difference[r];
        const double flux = nu * face_value;
        change[l] -= flux;
        change[r] += flux;
      }
    }
    const int last = row + (n - 1) * s;
    for (int inner = 0; inner < s; ++inner) {
      change[last + inner] -= courant[face_row + n * s + inner] * q[last + inner];
    }
  }
}

template class Advector<1>;
template class Advector<2>;
template class Advector<3>;

}  // namespace ice

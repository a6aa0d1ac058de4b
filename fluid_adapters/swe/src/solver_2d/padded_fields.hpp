#pragma once

#include <cstddef>
#include <vector>

namespace swe::solver_2d {

// Cells of the grid with two ghost layers on every side, x fastest: cell
// (i, j), -2 <= i < nx + 2, -2 <= j < ny + 2, sits at index(i, j). The four
// 2 x 2 corner blocks are never read (each direction reads its own line).
struct PaddedLayout {
  static constexpr std::ptrdiff_t ghosts = 2;
  std::ptrdiff_t nx = 0, ny = 0;

  std::ptrdiff_t stride() const { return nx + 2 * ghosts; }
  std::ptrdiff_t size() const { return stride() * (ny + 2 * ghosts); }
  std::ptrdiff_t index(std::ptrdiff_t i, std::ptrdiff_t j) const {
    return (i + ghosts) + (j + ghosts) * stride();
  }
};

// One shallow-water state on the padded cells (SoA): the conserved
// variables and the primitives the reconstruction reads, kept in step with
// them (eta = h + B; velocities zero in dry cells).
struct PaddedFields {
  std::vector<double> h, hu, hv;
  std::vector<double> eta, u, v;

  explicit PaddedFields(std::ptrdiff_t size = 0)
      : h(size), hu(size), hv(size), eta(size), u(size), v(size) {}
};

// Sets the primitives of cell c from its conserved variables and bed.
inline void update_primitives(PaddedFields& f, const double* bed, std::ptrdiff_t c,
                              double dry_depth) {
  const double h = f.h[c];
  f.eta[c] = h + bed[c];
  if (h >= dry_depth) {
    const double inv_h = 1.0 / h;
    f.u[c] = f.hu[c] * inv_h;
    f.v[c] = f.hv[c] * inv_h;
  } else {
    f.u[c] = 0.0;
    f.v[c] = 0.0;
  }
}

}  // namespace swe::solver_2d

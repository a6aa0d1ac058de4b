#include "solver_1d/ghost_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"
#include "solver_1d/line_cells.hpp"

namespace swe::solver_1d {

namespace {

// One side of the line seen from its boundary: `inner` walks from the cell
// next to the boundary into the domain, `outer` from the ghost next to the
// boundary outwards; `inward` is +1 on the left side and -1 on the right.
struct Side {
  double* h;
  double* q;
  std::ptrdiff_t inner0, inner1, outer0, outer1;
  double inward;
};

void fill_side(const Boundary& boundary, const Physics& physics, const Side& s) {
  double* h = s.h;
  double* q = s.q;
  switch (boundary.kind) {
    case BoundaryKind::wall:
      h[s.outer0] = h[s.inner0];
      q[s.outer0] = -q[s.inner0];
      h[s.outer1] = h[s.inner1];
      q[s.outer1] = -q[s.inner1];
      return;
    case BoundaryKind::transmissive:
      h[s.outer0] = h[s.outer1] = h[s.inner0];
      q[s.outer0] = q[s.outer1] = q[s.inner0];
      return;
    case BoundaryKind::inflow_discharge: {
      const double discharge = boundary.value;
      const double critical_depth = std::cbrt(discharge * discharge / physics.gravity);
      h[s.outer0] = h[s.outer1] = std::max(h[s.inner0], critical_depth);
      q[s.outer0] = q[s.outer1] = s.inward * discharge;
      return;
    }
    case BoundaryKind::fixed_depth: {
      // The invariant u - inward 2c travels out of the domain (u - 2c on the
      // left side, u + 2c on the right side) and is kept.
      const double h_i = h[s.inner0];
      const double u_i = h_i >= physics.dry_depth ? q[s.inner0] / h_i : 0.0;
      const double h_b = boundary.value;
      const double u_b =
          u_i -
          s.inward * 2.0 * (std::sqrt(physics.gravity * h_i) - std::sqrt(physics.gravity * h_b));
      h[s.outer0] = h[s.outer1] = h_b;
      q[s.outer0] = q[s.outer1] = h_b >= physics.dry_depth ? h_b * u_b : 0.0;
      return;
    }
  }
}

void check_boundary(const Boundary& boundary, const char* side) {
  if (boundary.kind != BoundaryKind::inflow_discharge && boundary.kind != BoundaryKind::fixed_depth)
    return;
  if (!std::isfinite(boundary.value) || boundary.value < 0.0) {
    throw cosim::InputError(
        fmt::format("Solver1d: {} boundary ({}) needs a finite value >= 0, got {}", side,
                    to_string(boundary.kind), boundary.value));
  }
}

}  // namespace

void fill_ghost_cells(const Boundaries1d& boundaries, const Physics& physics, std::size_t n,
                      double* h, double* q) {
  const auto last = static_cast<std::ptrdiff_t>(n + 1);  // index of the last interior cell
  fill_side(boundaries.left, physics, {h, q, 2, n >= 2 ? 3 : 2, 1, 0, +1.0});
  fill_side(boundaries.right, physics,
            {h, q, last, n >= 2 ? last - 1 : last, last + 1, last + 2, -1.0});
}

void fill_ghost_bed(std::size_t n, double* bed) {
  bed[0] = bed[1] = bed[ghost_layers];
  bed[n + 2] = bed[n + 3] = bed[n + 1];
}

void check_boundaries(const Boundaries1d& boundaries) {
  check_boundary(boundaries.left, "left");
  check_boundary(boundaries.right, "right");
}

}  // namespace swe::solver_1d

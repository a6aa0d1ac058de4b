#include "solver_2d/ghost_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace swe::solver_2d {

namespace {

// One side of the grid: `count` boundary cells, first at `first`, the next at
// +along; `inward` steps from a boundary cell into the domain; the outward
// normal points along -inward with sign `outward` (+1 on max sides, -1 on
// min sides); `depth` interior cells lie along inward.
struct Side {
  std::ptrdiff_t first, count, along, inward, depth;
  double outward;
  std::vector<double>* normal_discharge;
  std::vector<double>* tangential_discharge;
};

template <BoundaryKind kind>
void fill_side(const Side& side, const Boundary& boundary, const Physics& physics, PaddedFields& f,
               std::vector<double>& bed) {
  std::vector<double>& qn = *side.normal_discharge;
  std::vector<double>& qt = *side.tangential_discharge;
  const double g = physics.gravity, dry_depth = physics.dry_depth;
  for (std::ptrdiff_t n = 0; n < side.count; ++n) {
    const std::ptrdiff_t edge = side.first + n * side.along;
    for (std::ptrdiff_t layer = 1; layer <= PaddedLayout::ghosts; ++layer) {
      const std::ptrdiff_t ghost = edge - layer * side.inward;
      const std::ptrdiff_t source = kind == BoundaryKind::wall
                                        ? edge + std::min(layer - 1, side.depth - 1) * side.inward
                                        : edge;
      bed[ghost] = bed[source];
      if constexpr (kind == BoundaryKind::wall) {
        f.h[ghost] = f.h[source];
        qn[ghost] = -qn[source];
        qt[ghost] = qt[source];
      } else if constexpr (kind == BoundaryKind::transmissive) {
        f.h[ghost] = f.h[source];
        qn[ghost] = qn[source];
        qt[ghost] = qt[source];
      } else if constexpr (kind == BoundaryKind::inflow_discharge) {
        const double q = boundary.value;
        f.h[ghost] = f.h[source] >= dry_depth ? f.h[source] : std::cbrt(q * q / g);
        qn[ghost] = -side.outward * q;
        qt[ghost] = 0.0;
      } else {
        const double h_i = f.h[source];
        const bool wet = h_i >= dry_depth;
        const double un_i = wet ? qn[source] / h_i : 0.0;
        const double ut_i = wet ? qt[source] / h_i : 0.0;
        const double h_b = boundary.value;
        // Outgoing invariant u_n + 2c (max side) or u_n - 2c (min side) kept.
        const double un_b = un_i + side.outward * 2.0 * (std::sqrt(g * h_i) - std::sqrt(g * h_b));
        f.h[ghost] = h_b;
        qn[ghost] = h_b * un_b;
        qt[ghost] = h_b * ut_i;
      }
      update_primitives(f, bed.data(), ghost, dry_depth);
    }
  }
}

void fill_side(const Side& side, const Boundary& boundary, const Physics& physics, PaddedFields& f,
               std::vector<double>& bed) {
  switch (boundary.kind) {
    case BoundaryKind::wall:
      return fill_side<BoundaryKind::wall>(side, boundary, physics, f, bed);
    case BoundaryKind::transmissive:
      return fill_side<BoundaryKind::transmissive>(side, boundary, physics, f, bed);
    case BoundaryKind::inflow_discharge:
      return fill_side<BoundaryKind::inflow_discharge>(side, boundary, physics, f, bed);
    case BoundaryKind::fixed_depth:
      return fill_side<BoundaryKind::fixed_depth>(side, boundary, physics, f, bed);
  }
}

// The four sides of `layout`, x_min, x_max, y_min, y_max.
std::array<Side, 4> sides(const PaddedLayout& layout, PaddedFields& fields) {
  const std::ptrdiff_t nx = layout.nx, ny = layout.ny, sx = layout.stride();
  std::vector<double>* hu = &fields.hu;
  std::vector<double>* hv = &fields.hv;
  return {Side{layout.index(0, 0), ny, sx, 1, nx, -1.0, hu, hv},
          Side{layout.index(nx - 1, 0), ny, sx, -1, nx, 1.0, hu, hv},
          Side{layout.index(0, 0), nx, 1, sx, ny, -1.0, hv, hu},
          Side{layout.index(0, ny - 1), nx, 1, -sx, ny, 1.0, hv, hu}};
}

}  // namespace

void fill_ghost_cells(const PaddedLayout& layout, const Boundaries2d& boundaries,
                      const std::array<bool, 4>& linked, const Physics& physics,
                      PaddedFields& fields, std::vector<double>& bed) {
  const Boundary* boundary[4] = {&boundaries.x_min, &boundaries.x_max, &boundaries.y_min,
                                 &boundaries.y_max};
  const std::array<Side, 4> all = sides(layout, fields);
  for (std::size_t s = 0; s < 4; ++s)
    if (!linked[s]) fill_side(all[s], *boundary[s], physics, fields, bed);
}

void update_linked_ghost_primitives(const PaddedLayout& layout, const std::array<bool, 4>& linked,
                                    const Physics& physics, PaddedFields& fields,
                                    const std::vector<double>& bed) {
  const std::array<Side, 4> all = sides(layout, fields);
  for (std::size_t s = 0; s < 4; ++s) {
    if (!linked[s]) continue;
    const Side& side = all[s];
    for (std::ptrdiff_t n = 0; n < side.count; ++n)
      for (std::ptrdiff_t layer = 1; layer <= PaddedLayout::ghosts; ++layer)
        update_primitives(fields, bed.data(), side.first + n * side.along - layer * side.inward,
                          physics.dry_depth);
  }
}

}  // namespace swe::solver_2d

#pragma once

#include <cstddef>
#include <vector>

#include "solver_2d/directional_sweep.hpp"
#include "solver_2d/padded_fields.hpp"
#include "swe/physics.hpp"
#include "swe/scheme.hpp"

namespace swe::solver_2d {

// Row buffers of one thread: the x reconstruction and faces of the row being
// updated, and the y reconstructions and faces of the rows below and at it.
struct StageWorkspace {
  ReconstructedCells x_cells;       // cells -1 .. nx of the row
  std::vector<FaceFluxes> x_faces;  // faces 0 .. nx of the row
  ReconstructedCells y_cells[2];
  std::vector<FaceFluxes> y_faces[2];

  void resize(std::ptrdiff_t nx);
};

// One explicit stage of SSP-RK2 (Heun; Gottlieb & Shu, Math. Comp. 67, 1998):
//   out = base_weight * base + (1 - base_weight) * (in - dt (R_x(in) + R_y(in)))
// (stage 1: base_weight 0; stage 2: base = U^n, base_weight 1/2; `out` may be
// `base`). Then round-off negative depths become 0, dry cells lose their
// momentum and, when `with_friction`, the semi-implicit Manning step
// (Zheng et al., eq. 36) follows. The primitives of `out` are updated; its
// ghost cells are left to the caller.
struct StageArguments {
  PaddedLayout layout;
  const Physics* physics;
  const Scheme* scheme;
  const double* bed;
  double dt;
  double inv_dx, inv_dy;
  double base_weight;
  bool with_friction;
};

void runge_kutta_stage(const StageArguments& args, const PaddedFields& in, const PaddedFields& base,
                       PaddedFields& out, std::vector<StageWorkspace>& workspaces);

// Rows are updated on several threads above this many cells.
inline constexpr std::ptrdiff_t parallel_cell_count = 8192;

}  // namespace swe::solver_2d

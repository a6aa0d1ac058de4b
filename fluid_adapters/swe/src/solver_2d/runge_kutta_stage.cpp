#include "solver_2d/runge_kutta_stage.hpp"

#include <omp.h>

#include <algorithm>
#include <utility>

#include "solver_2d/row_update.hpp"

namespace swe::solver_2d {

void StageWorkspace::resize(std::ptrdiff_t nx) {
  x_cells.resize(nx + 2);
  x_faces.resize(nx + 1);
  for (int k = 0; k < 2; ++k) {
    y_cells[k].resize(nx);
    y_faces[k].resize(nx);
  }
}

namespace {

// Rows first_row .. end_row - 1: per face the MUSCL reconstruction (van
// Leer, J. Comput. Phys. 32, 1979), the hydrostatic reconstruction (Audusse
// et al., SIAM J. Sci. Comput. 25, 2004) and the Riemann solver, then the
// row's update (see runge_kutta_stage). The y faces of the rows are computed once
// each (the lowest one per block of rows twice), row by row, so the working
// set stays a few rows.
template <FluxKind flux, LimiterKind limiter, bool with_friction>
void advance_rows(const StageArguments& a, const PaddedFields& in, const PaddedFields& base,
                  PaddedFields& out, std::ptrdiff_t first_row, std::ptrdiff_t end_row,
                  StageWorkspace& ws) {
  const PaddedLayout& layout = a.layout;
  const std::ptrdiff_t nx = layout.nx, sx = layout.stride();
  const double g = a.physics->gravity;
  const UpdateConstants constants{
      a.dt, a.inv_dx, a.inv_dy, a.base_weight, g, a.physics->dry_depth, a.physics->manning};
  const PrimitiveView p{in.h.data(), in.eta.data()};
  const double* u = in.u.data();
  const double* v = in.v.data();

  ReconstructedCells* y_row = &ws.y_cells[0];       // row j
  ReconstructedCells* y_adjacent = &ws.y_cells[1];  // row j - 1, then row j + 1
  FaceFluxes* y_faces_below = ws.y_faces[0].data();
  FaceFluxes* y_faces_above = ws.y_faces[1].data();
  ReconstructedCells& x_cells = ws.x_cells;
  FaceFluxes* x_faces = ws.x_faces.data();

  reconstruct_cells<limiter>(p, v, u, layout.index(0, first_row - 1), nx, sx, *y_adjacent);
  reconstruct_cells<limiter>(p, v, u, layout.index(0, first_row), nx, sx, *y_row);
  face_fluxes<flux>(*y_adjacent, 0, *y_row, 0, nx, g, y_faces_below);
  for (std::ptrdiff_t j = first_row; j < end_row; ++j) {
    reconstruct_cells<limiter>(p, v, u, layout.index(0, j + 1), nx, sx, *y_adjacent);
    face_fluxes<flux>(*y_row, 0, *y_adjacent, 0, nx, g, y_faces_above);
    reconstruct_cells<limiter>(p, u, v, layout.index(-1, j), nx + 2, 1, x_cells);
    face_fluxes<flux>(x_cells, 0, x_cells, 1, nx + 1, g, x_faces);

    const std::ptrdiff_t row = layout.index(0, j);
    const RowUpdate update{x_faces,
                           y_faces_below,
                           y_faces_above,
                           FaceSides(x_cells, 1),
                           FaceSides(*y_row, 0),
                           in.h.data() + row,
                           in.hu.data() + row,
                           in.hv.data() + row,
                           base.h.data() + row,
                           base.hu.data() + row,
                           base.hv.data() + row,
                           a.bed + row,
                           out.h.data() + row,
                           out.hu.data() + row,
                           out.hv.data() + row,
                           out.eta.data() + row,
                           out.u.data() + row,
                           out.v.data() + row};
    update_row<with_friction>(update, nx, constants);
    std::swap(y_row, y_adjacent);
    std::swap(y_faces_below, y_faces_above);
  }
}

template <FluxKind flux, LimiterKind limiter, bool with_friction>
void advance(const StageArguments& a, const PaddedFields& in, const PaddedFields& base,
             PaddedFields& out, std::vector<StageWorkspace>& workspaces) {
  const std::ptrdiff_t ny = a.layout.ny;
  const bool parallel = a.layout.nx * ny > parallel_cell_count;
  const std::ptrdiff_t blocks = parallel ? std::min<std::ptrdiff_t>(omp_get_max_threads(), ny) : 1;
  if (std::ssize(workspaces) < blocks) workspaces.resize(blocks);
  for (std::ptrdiff_t b = 0; b < blocks; ++b) workspaces[b].resize(a.layout.nx);
#pragma omp parallel for schedule(static) if (parallel)
  for (std::ptrdiff_t b = 0; b < blocks; ++b) {
    advance_rows<flux, limiter, with_friction>(a, in, base, out, ny * b / blocks,
                                               ny * (b + 1) / blocks, workspaces[b]);
  }
}

template <FluxKind flux, LimiterKind limiter>
void advance(const StageArguments& a, const PaddedFields& in, const PaddedFields& base,
             PaddedFields& out, std::vector<StageWorkspace>& workspaces) {
  if (a.with_friction && a.physics->manning > 0.0) {
    advance<flux, limiter, true>(a, in, base, out, workspaces);
  } else {
    advance<flux, limiter, false>(a, in, base, out, workspaces);
  }
}

template <FluxKind flux>
void advance(const StageArguments& a, const PaddedFields& in, const PaddedFields& base,
             PaddedFields& out, std::vector<StageWorkspace>& workspaces) {
  switch (a.scheme->limiter) {
    case LimiterKind::none:
      return advance<flux, LimiterKind::none>(a, in, base, out, workspaces);
    case LimiterKind::minmod:
      return advance<flux, LimiterKind::minmod>(a, in, base, out, workspaces);
    case LimiterKind::van_leer:
      return advance<flux, LimiterKind::van_leer>(a, in, base, out, workspaces);
    case LimiterKind::monotonized_central:
      return advance<flux, LimiterKind::monotonized_central>(a, in, base, out, workspaces);
  }
}

}  // namespace

void runge_kutta_stage(const StageArguments& args, const PaddedFields& in, const PaddedFields& base,
                       PaddedFields& out, std::vector<StageWorkspace>& workspaces) {
  switch (args.scheme->flux) {
    case FluxKind::roe:
      return advance<FluxKind::roe>(args, in, base, out, workspaces);
    case FluxKind::hll:
      return advance<FluxKind::hll>(args, in, base, out, workspaces);
    case FluxKind::hllc:
      return advance<FluxKind::hllc>(args, in, base, out, workspaces);
  }
}

}  // namespace swe::solver_2d

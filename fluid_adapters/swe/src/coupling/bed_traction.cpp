#include "swe/coupling/bed_traction.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "cosim/error.hpp"
#include "swe/numerics/hydrostatic_reconstruction.hpp"
#include "swe/numerics/manning_friction.hpp"

namespace swe {

namespace {

// Horizontal force of the water on the bed at the face between cells l and r
// [N per m of face], positive along +x (or +y).
double bed_face_force(std::span<const double> h, std::span<const double> bed, std::size_t l,
                      std::size_t r, double g, double density) {
  const HydrostaticFace f = hydrostatic_face(h[l], bed[l], h[r], bed[r], g);
  return density * (f.left_correction - f.right_correction);
}

}  // namespace

std::vector<double> bed_traction(const Solver& solver, const CouplingSpec& spec) {
  const int dim = solver.dimension();
  const auto components = static_cast<std::size_t>(dim + 1);
  const std::size_t n = solver.cell_count();
  const Physics& physics = solver.physics();
  const double g = physics.gravity, rho = physics.density;
  const auto h = solver.depth();
  const auto bed = solver.bed();
  if (spec.pressure == BedPressure::excess && spec.initial_surface.size() != n)
    throw cosim::Error(cosim::ExitCode::internal_error,
                       fmt::format("bed traction: {} initial free-surface values for {} cells",
                                   spec.initial_surface.size(), n));
  const auto qx = solver.discharge_x();
  const auto qy = solver.discharge_y();
  std::vector<double> traction(n * components, 0.0);

  for (std::size_t c = 0; c < n; ++c) {
    double* t = traction.data() + c * components;
    const bool wet = h[c] > physics.dry_depth;
    if (wet) {
      const double u = qx[c] / h[c];
      const double v = dim == 2 ? qy[c] / h[c] : 0.0;
      const double speed = std::hypot(u, v);
      t[0] = manning_bed_shear(h[c], u, speed, g, physics.manning, rho);
      if (dim == 2) t[1] = manning_bed_shear(h[c], v, speed, g, physics.manning, rho);
    }
    double& vertical = t[components - 1];
    if (spec.pressure == BedPressure::hydrostatic)
      vertical = -rho * g * h[c];
    else if (wet)
      vertical = -rho * g * std::max(0.0, h[c] + bed[c] - spec.initial_surface[c]);
  }
  if (spec.pressure != BedPressure::hydrostatic) return traction;

  auto add_face = [&](std::size_t l, std::size_t r, std::size_t axis, double width_l,
                      double width_r) {
    const double f = bed_face_force(h, bed, l, r, g, rho);
    traction[l * components + axis] += 0.5 * f / width_l;
    traction[r * components + axis] += 0.5 * f / width_r;
  };
  const cosim::MeshGeometry cells = solver.cells();
  if (const auto* line = std::get_if<cosim::NonUniformLine>(&cells)) {
    for (std::size_t i = 0; i + 1 < n; ++i)
      add_face(i, i + 1, 0, line->width(i), line->width(i + 1));
  } else {
    const auto& grid = std::get<cosim::UniformGrid>(cells);
    const auto nx = static_cast<std::size_t>(grid.cells[0]),
               ny = static_cast<std::size_t>(grid.cells[1]);
    const double dx = grid.spacing[0], dy = grid.spacing[1];
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) add_face(j * nx + i, j * nx + i + 1, 0, dx, dx);
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) add_face(j * nx + i, (j + 1) * nx + i, 1, dy, dy);
  }
  return traction;
}

}  // namespace swe

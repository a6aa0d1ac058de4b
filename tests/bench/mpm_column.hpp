#pragma once

// The collapsing Mohr-Coulomb column the MPM benchmarks time (mpm_bench,
// mpm_mpi_bench): points seeded 2 per cell and direction, the column in a
// corner of the grid (slip walls, fixed base) with room to spread sideways.
#include <memory>
#include <utility>

#include "cosim/config/document.hpp"
#include "mpm/case/case_description.hpp"
#include "mpm/material/material_registry.hpp"

namespace bench {

// Mohr-Coulomb sand with a small cohesion, so the free surfaces yield.
inline std::shared_ptr<const mpm::Material> sand() {
  const auto document = cosim::config::Document::load_string(
      "type: mohr_coulomb\ndensity: 2000\nyoungs_modulus: 1.0e7\npoisson_ratio: 0.3\n"
      "friction_angle: 30\ndilation_angle: 0\ncohesion: 100\ntensile_strength: 50\n",
      "mpm_bench_sand.yaml");
  return mpm::make_material(document.root());
}

// A column `wide` cells wide (2D: twice as high; 3D: a cube) of the given
// dimension and shape, on `threads` OpenMP threads.
inline mpm::CaseDescription column_case(int dim, int wide, mpm::ShapeKind shape, int threads) {
  const double h = 0.1;
  const int ppc = 2;  // per direction
  const int high = dim == 2 ? 2 * wide : wide;
  mpm::CaseDescription c;
  c.name = "mpm_bench_column";
  c.dimension = dim;
  c.grid.spacing = mpm::Vec3d::Constant(h);
  const int spread = wide + wide / 2;  // room for the toe
  c.grid.cells = {spread, dim == 3 ? spread : high + 4, dim == 3 ? high + 4 : 1};
  c.shape = shape;
  c.scheme = mpm::UpdateScheme::musl;
  c.gravity = dim == 2 ? mpm::Vec3d(0, -9.81, 0) : mpm::Vec3d(0, 0, -9.81);
  c.threads = threads;
  c.materials.push_back(sand());
  c.material_names.push_back("sand");
  const int up = dim - 1;
  for (int d = 0; d < dim; ++d) {
    c.boundaries[static_cast<std::size_t>(2 * d)].kind = mpm::FaceCondition::Kind::slip;
    c.boundaries[static_cast<std::size_t>(2 * d + 1)].kind = mpm::FaceCondition::Kind::slip;
  }
  c.boundaries[static_cast<std::size_t>(2 * up)].kind = mpm::FaceCondition::Kind::fixed;

  mpm::BodySpec body;
  body.name = "column";
  body.material = 0;
  const double d = h / ppc;
  const int n = wide * ppc;
  const int nup = high * ppc;
  const int nz = dim == 3 ? nup : 1;
  const int ny = dim == 3 ? n : nup;
  const auto count =
      static_cast<std::size_t>(n) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
  body.positions.reserve(count);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < n; ++i)
        body.positions.emplace_back((i + 0.5) * d, (j + 0.5) * d, dim == 3 ? (k + 0.5) * d : 0.0);
  body.volumes.assign(count, dim == 3 ? d * d * d : d * d);
  body.half_lengths.assign(count, mpm::Vec3d::Constant(0.5 * d));
  body.geostatic = mpm::GeostaticStress{};
  c.bodies.push_back(std::move(body));
  return c;
}

}  // namespace bench

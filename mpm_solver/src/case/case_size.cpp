#include "case/case_size.hpp"

#include <cstdint>
#include <limits>

namespace mpm::case_loading {

namespace {

using cosim::config::Node;

// Memory of a run, measured as the peak resident set (GNU time's %M) of
// `mpm_solver` on a box of linear-elastic soil (MUSL, GIMP, 3 steps,
// snapshots at the start and end, 2 threads) and fitted by least squares
// (residuals below 5 MB): 2D, 25 600 to 921 600 particles on 10 201 nodes
// and 40 401 to 2 253 001 nodes under 400 particles; 3D, 64 000 to 10^6
// particles on 29 791 nodes and 68 921 to 1 771 561 nodes under 512
// particles. The figures include the case description, the particles'
// arrays, the seeding's temporaries, the particle bins and the snapshot
// writer's buffers; a grid value's is for one velocity field (contact and
// rigid bodies add fields) and leaves out heat conduction (4 more doubles).
constexpr double bytes_per_particle_2d = 697.0;
constexpr double bytes_per_particle_3d = 810.0;
constexpr double bytes_per_grid_value_2d = 88.0;
constexpr double bytes_per_grid_value_3d = 128.0;
// The program with an empty case: code, libraries, HDF5 and OpenMP.
constexpr double program_bytes = 21e6;

// The particle bins index particles with 32-bit unsigned integers.
constexpr double most_particles = std::numeric_limits<std::uint32_t>::max();
constexpr double most_grid_values = static_cast<double>(std::numeric_limits<std::int64_t>::max());

}  // namespace

int velocity_fields(const Node& case_root) {
  bool contact = false;
  if (auto c = case_root.find("contact")) contact = c->get<bool>("enabled", false);
  int rigid = 0, deformable = 0;
  for (const Node& body : case_root["bodies"].items())
    (body.has("rigid") ? rigid : deformable) += 1;
  const int fields = rigid + (contact ? deformable : (deformable > 0 ? 1 : 0));
  return fields > 0 ? fields : 1;
}

cosim::RunSize run_size(const GridDemand& demand, double particles, const Node& case_root) {
  const bool plane = demand.dimension == 2;
  // Grid values per direction: the nodes, or the B-spline's control points.
  const int extra = demand.shape == ShapeKind::quadratic_bspline ? 2 : 1;
  double values = 1.0;
  for (int d = 0; d < demand.dimension; ++d)
    values *= static_cast<double>(demand.grid.cells[static_cast<std::size_t>(d)]) + extra;
  cosim::RunSize size;
  size.fixed_bytes = program_bytes;
  size.add({"particles", particles, plane ? bytes_per_particle_2d : bytes_per_particle_3d,
            most_particles, case_root["bodies"]});
  size.add({"grid nodes", values,
            demand.velocity_fields * (plane ? bytes_per_grid_value_2d : bytes_per_grid_value_3d),
            most_grid_values, case_root["grid"]["cells"]});
  return size;
}

}  // namespace mpm::case_loading

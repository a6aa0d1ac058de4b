#include "ice/case/case_size.hpp"

#include <limits>

namespace ice {

namespace {

// Memory of a run, measured as the peak resident set (GNU time's %M) of
// `ice_fluid` (3 steps, snapshots at the start and end, 2 threads) and
// fitted by least squares against the cells (residuals below 0.6 MB), with
// one, two and three materials: 1D 10^5 to 2 10^6 cells, 2D 200^2 to 800^2,
// 3D 30^3 to 80^3. Per cell, a part the materials share (pressure, its
// solver's matrix and multigrid levels, face velocities) and a part per
// material (mass, momentum, energy, volume fraction and their face values).
// Index: the dimension.
constexpr double shared_bytes_per_cell[] = {0.0, 436.0, 548.0, 647.0};
constexpr double bytes_per_cell_and_material[] = {0.0, 192.0, 224.0, 281.0};
// The program with a one-cell case: code, libraries, HDF5 and OpenMP.
constexpr double program_bytes = 20.5e6;

// Cells and faces are indexed with int.
constexpr double most_cells = std::numeric_limits<int>::max();

}  // namespace

cosim::RunSize run_size(int dimension, double cells, int materials,
                        const cosim::config::Node& case_root) {
  const auto d = static_cast<std::size_t>(dimension);
  cosim::RunSize size;
  size.fixed_bytes = program_bytes;
  size.add({"cells", cells, shared_bytes_per_cell[d] + materials * bytes_per_cell_and_material[d],
            most_cells, case_root["grid"]["cells"]});
  return size;
}

}  // namespace ice

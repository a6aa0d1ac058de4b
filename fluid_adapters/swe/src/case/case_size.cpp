#include "swe/case/case_size.hpp"

#include <cstdint>
#include <limits>

namespace swe {

namespace {

// Memory of a run, measured as the peak resident set (GNU time's %M) of
// `swe_fluid` on a dam break (3 to 5 steps, snapshots at the start and end,
// 2 threads) and fitted by least squares: 1D, 10^5 to 10^7 cells
// (residuals below 0.2 MB); 2D, 200^2 to 2500^2 cells (residuals below
// 17 MB). The figures include the solver's state and padded work arrays,
// the case's edges and bed, the cells' mesh and the snapshot writer's
// buffers.
constexpr double bytes_per_cell_1d = 152.0;
constexpr double bytes_per_cell_2d = 207.0;
// The program with a one-cell case: code, libraries, HDF5 and OpenMP.
constexpr double program_bytes = 20e6;

// Cells are indexed with std::ptrdiff_t.
constexpr double most_cells = static_cast<double>(std::numeric_limits<std::int64_t>::max());

}  // namespace

cosim::RunSize run_size(int dimension, double cells, const cosim::config::Node& case_root) {
  cosim::RunSize size;
  size.fixed_bytes = program_bytes;
  size.add({"cells", cells, dimension == 1 ? bytes_per_cell_1d : bytes_per_cell_2d, most_cells,
            case_root["mesh"]});
  return size;
}

}  // namespace swe

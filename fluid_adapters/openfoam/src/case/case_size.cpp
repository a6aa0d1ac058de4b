#include "openfoam/case/case_size.hpp"

#include <limits>

#include "openfoam/case/mesh_cell_count.hpp"

namespace openfoam {

namespace {

// Memory of a run, measured on generated dam breaks (2 windows of one step,
// serial): the adapter's peak resident set (VmHWM, polled every 20 ms) and
// that of the solver it starts, fitted by least squares against the cells
// (residuals below 3 MB): 2D 5 000 to 180 000 cells, 3D 16 000 to 250 000.
// Per cell, the adapter 208 (2D) to 240 (3D) bytes: the mesh's centres and
// volumes, the fields it reads back every window and the snapshot writer's
// buffers; interFoam 1445 (2D) to 1676 (3D); MPPICInterFoam 2195 to 2246
// (without parcels: a coupled soil adds one per soil cell). blockMesh,
// setFields and postProcess, run before or between the solver's starts,
// take less. The largest of each is used.
constexpr double adapter_bytes_per_cell = 240.0;
constexpr double solver_bytes_per_cell = 1676.0;
constexpr double cloud_solver_bytes_per_cell = 2246.0;
// The adapter with a one-cell case, and each OpenFOAM solver process.
constexpr double adapter_bytes = 20e6;
constexpr double solver_process_bytes = 99e6;
constexpr double cloud_solver_process_bytes = 111e6;

// OpenFOAM (Debian's build) labels cells with 32-bit integers.
constexpr double most_cells = std::numeric_limits<int>::max();

}  // namespace

cosim::RunSize run_size(const CaseDescription& c, const cosim::config::Node& case_root) {
  cosim::RunSize size;
  size.fixed_bytes = adapter_bytes + c.processes * (c.has_cloud() ? cloud_solver_process_bytes
                                                                  : solver_process_bytes);
  const double per_cell = adapter_bytes_per_cell +
                          (c.has_cloud() ? cloud_solver_bytes_per_cell : solver_bytes_per_cell);
  if (c.generate) {
    double cells = 1.0;
    for (int n : c.generate->cells) cells *= n;
    size.add({"cells", cells, per_cell, most_cells, case_root["generate"]["grid"]["cells"]});
  } else if (const auto cells = mesh_cell_count(c.directory)) {
    size.add({"cells", *cells, per_cell, most_cells, case_root["directory"]});
  } else {
    size.not_included =
        "the cells of the OpenFOAM case in " + c.directory.string() +
        " (no constant/polyMesh/owner stating them, no blockMeshDict of plain hex blocks)";
  }
  return size;
}

}  // namespace openfoam

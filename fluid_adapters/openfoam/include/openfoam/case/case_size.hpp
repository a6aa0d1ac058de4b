#pragma once

#include "cosim/config/node.hpp"
#include "cosim/io/run_size.hpp"
#include "openfoam/case/case_description.hpp"

namespace openfoam {

// The size of a run: the mesh's cells (the generated grid's, or a user
// case's as mesh_cell_count reads them) and the memory of the adapter and
// of OpenFOAM's solver processes, as measured. A user case whose cells
// cannot be counted says so (RunSize::not_included) and is estimated
// without them.
cosim::RunSize run_size(const CaseDescription& c, const cosim::config::Node& case_root);

}  // namespace openfoam

#pragma once

#include <filesystem>
#include <optional>

#include "cosim/mesh.hpp"
#include "openfoam/case/case_description.hpp"
#include "openfoam/case/case_properties.hpp"
#include "openfoam/foam/installation.hpp"

namespace openfoam {

// The cells of the OpenFOAM case as the adapter declares them: their
// centres and volumes written by OpenFOAM's own postProcess
// (writeCellCentres, writeCellVolumes) at time 0. A generated case is
// checked to be the uniform grid it was made as (blockMesh numbers the
// cells x fastest) and declared as that grid; a user's case is a cell cloud
// (in 2D its cells' x and y and their volumes per unit depth).
struct CaseMesh {
  cosim::Mesh mesh;
  std::vector<double> centres;  // x, y, z per cell
  std::vector<double> volumes;
};

CaseMesh read_case_mesh(const Installation& installation, const std::filesystem::path& case_dir,
                        const std::filesystem::path& log_dir,
                        const std::optional<GeneratedCase>& generated,
                        const CaseProperties& properties, const std::string& name);

}  // namespace openfoam

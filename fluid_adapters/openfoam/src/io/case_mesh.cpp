#include "openfoam/io/case_mesh.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "cosim/error.hpp"
#include "openfoam/foam/field_file.hpp"
#include "openfoam/foam/foam_application.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

// How many cells polyMesh/owner's header note says the mesh has ("nCells:N").
std::size_t mesh_cell_count(const fs::path& case_dir) {
  const fs::path owner = case_dir / "constant" / "polyMesh" / "owner";
  std::ifstream in(owner);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const auto at = head.find("nCells:");
  if (at == std::string::npos) {
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       fmt::format("{}: no nCells in its header note", owner.string()));
  }
  return static_cast<std::size_t>(std::stoull(head.substr(at + 7)));
}

// A generated case's cells must be the grid it was made as.
void check_generated_grid(const GeneratedCase& g, const std::vector<double>& centres,
                          const std::vector<double>& volumes) {
  const Vector3 h = g.spacing();
  const double cell_volume = h[0] * h[1] * h[2];
  std::size_t c = 0;
  for (int k = 0; k < g.cells[2]; ++k) {
    for (int j = 0; j < g.cells[1]; ++j) {
      for (int i = 0; i < g.cells[0]; ++i, ++c) {
        const int index[3] = {i, j, k};
        for (std::size_t d = 0; d < 3; ++d) {
          const double expected = g.origin[d] + (index[d] + 0.5) * h[d];
          if (std::abs(centres[3 * c + d] - expected) > 1e-6 * h[d]) {
            throw cosim::Error(
                cosim::ExitCode::participant_failed,
                fmt::format("the OpenFOAM mesh does not match the generated grid: cell {} has "
                            "its centre at {} along {}, the grid's is at {}",
                            c, centres[3 * c + d], "xyz"[d], expected));
          }
        }
        if (std::abs(volumes[c] - cell_volume) > 1e-6 * cell_volume) {
          throw cosim::Error(cosim::ExitCode::participant_failed,
                             fmt::format("the OpenFOAM mesh does not match the generated grid: "
                                         "cell {} has volume {}, the grid's cells {}",
                                         c, volumes[c], cell_volume));
        }
      }
    }
  }
}

}  // namespace

CaseMesh read_case_mesh(const Installation& installation, const fs::path& case_dir,
                        const fs::path& log_dir, const std::optional<GeneratedCase>& generated,
                        const CaseProperties& properties, const std::string& name) {
  run_application(installation, "postProcess", {"-func", "writeCellCentres", "-time", "0"},
                  case_dir, log_dir / "postProcess.log");
  run_application(installation, "postProcess", {"-func", "writeCellVolumes", "-time", "0"},
                  case_dir, log_dir / "postProcess.log");
  const std::size_t cells = mesh_cell_count(case_dir);
  CaseMesh m;
  m.centres = read_internal_field(case_dir / "0" / "C", FieldType::vector, cells);
  m.volumes = read_internal_field(case_dir / "0" / "V", FieldType::scalar, cells);
  // The solver must not find them in its start directory.
  for (const char* f : {"C", "Cx", "Cy", "Cz", "V"}) fs::remove(case_dir / "0" / f);
  if (generated) {
    const GeneratedCase& g = *generated;
    if (cells != g.cell_count()) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("the OpenFOAM mesh has {} cells, the generated grid {}", cells,
                                     g.cell_count()));
    }
    check_generated_grid(g, m.centres, m.volumes);
    cosim::UniformGrid grid;
    grid.dim = g.dimension;
    const Vector3 h = g.spacing();
    for (std::size_t d = 0; d < static_cast<std::size_t>(g.dimension); ++d) {
      grid.origin[d] = g.origin[d];
      grid.spacing[d] = h[d];
      grid.cells[d] = g.cells[d];
    }
    grid.location = cosim::GridLocation::cell;
    m.mesh = {name, grid};
  } else {
    // A 2D case's cells in its x-y plane, per unit depth.
    cosim::CellCloud cloud;
    cloud.dim = properties.dimension;
    const auto dim = static_cast<std::size_t>(cloud.dim);
    cloud.centres.resize(cells * dim);
    cloud.volumes.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) {
      for (std::size_t d = 0; d < dim; ++d) cloud.centres[c * dim + d] = m.centres[3 * c + d];
      cloud.volumes[c] = properties.declared_volume(m.volumes[c]);
    }
    m.mesh = {name, cloud};
  }
  cosim::validate(m.mesh);
  return m;
}

}  // namespace openfoam

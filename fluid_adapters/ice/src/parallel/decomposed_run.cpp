#include "ice/parallel/decomposed_run.hpp"

#include <fmt/format.h>

#include <string>

#include "cosim/error.hpp"
#include "cosim/io/partitioned_snapshot_writer.hpp"
#include "ice/case/make_solver.hpp"

namespace ice::parallel {

namespace {

// What a decomposed run does not do yet: refused before any rank builds.
const CaseDescription& runnable(const CaseDescription& c, MPI_Comm comm) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const auto refuse = [&](const std::string& key, const std::string& what) {
    throw cosim::InputError(fmt::format("{}: key '{}': {} runs on one process; mpirun started {}",
                                        c.file.string(), key, what, ranks));
  };
  if (c.numerics.pressure_solver == NumericsDescription::PressureSolverKind::builtin)
    refuse("numerics.pressure.solver", "the built-in pressure solver");
  return c;
}

cosim::InputError refused_options(const CaseDescription& c, const PetscOptionsRefused& e) {
  return cosim::InputError(cosim::SourceLocation{c.file.string(), 0, 0},
                           "numerics.pressure.petsc_options", e.what());
}

template <int Dim>
BlockSolver<Dim> block_of(MPI_Comm comm, const CaseDescription& c) {
  try {
    return make_block_solver<Dim>(comm, runnable(c, comm), petsc_pressure_options(c));
  } catch (const PetscOptionsRefused& e) {
    throw refused_options(c, e);
  } catch (const cosim::InputError& e) {
    if (std::string(e.what()).find(c.file.string()) == 0) throw;
    throw cosim::InputError(fmt::format("{}: key 'grid.cells': {}", c.file.string(), e.what()));
  }
}

}  // namespace

PetscPressureOptions petsc_pressure_options(const CaseDescription& c) {
  PetscPressureOptions options;
  options.tolerance = c.numerics.pressure.tolerance;
  options.max_iterations = c.numerics.pressure.max_iterations;
  options.preconditioner = c.numerics.petsc_preconditioner;
  options.petsc_options = c.numerics.petsc_options;
  return options;
}

template <int Dim>
DecomposedRun<Dim>::DecomposedRun(MPI_Comm comm, const CaseDescription& description)
    : comm_(comm), whole_(case_grid<Dim>(description)), block_(block_of<Dim>(comm, description)) {}

template <int Dim>
std::optional<typename GaugeRecorder<Dim>::Decomposed> DecomposedRun<Dim>::gauge_cells(
    const IceSolver<Dim>& solver) const {
  const auto offset = block_.link->offset();
  const auto owned = block_.link->owned_cells();
  const CellGrid<Dim>& block = solver.grid();
  const CellGrid<Dim>& whole = whole_;
  return typename GaugeRecorder<Dim>::Decomposed{
      whole_, [offset, owned, block, whole](int cell) {
        auto ijk = whole.cell_ijk(cell);
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
          ijk[d] -= offset[d];
          if (ijk[d] < owned[d][0] || ijk[d] >= owned[d][1]) return -1;
        }
        return block.cell(ijk);
      }};
}

template <int Dim>
std::optional<cosim::decomposition::StoredBlock> DecomposedRun<Dim>::block() const {
  const auto& halo = block_.link->halo();
  const auto offset = block_.link->offset();
  cosim::decomposition::StoredBlock b{halo.block().cells, halo.block().cells, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
    b.stored[d] = {offset[d], offset[d] + halo.padded_extent()[d]};
  return b;
}

template <int Dim>
std::optional<typename RunRanks<Dim>::CellsPart> DecomposedRun<Dim>::coupling_cells(
    const IceSolver<Dim>& solver, const std::string& mesh_name) const {
  cosim::Mesh whole = cell_mesh(whole_, mesh_name);
  const auto offset = block_.link->offset();
  const auto owned = block_.link->owned_cells();
  cosim::Index3 lower{0, 0, 0}, upper{1, 1, 1}, owned_lower{0, 0, 0}, owned_upper{1, 1, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    lower[d] = offset[d];
    upper[d] = offset[d] + solver.grid().cells()[d];
    owned_lower[d] = offset[d] + owned[d][0];
    owned_upper[d] = offset[d] + owned[d][1];
  }
  cosim::MeshPart part = cosim::MeshPart::box(std::get<cosim::UniformGrid>(whole.geometry), lower,
                                              upper, owned_lower, owned_upper);
  return typename RunRanks<Dim>::CellsPart{std::move(whole), std::move(part)};
}

template <int Dim>
void DecomposedRun<Dim>::sum(std::span<double> values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
}

template <int Dim>
std::unique_ptr<IceSolver<Dim>> DecomposedRun<Dim>::make_solver(const CaseDescription&) {
  if (!block_.solver) throw std::logic_error("DecomposedRun: the block's solver was taken");
  return std::move(block_.solver);
}

template <int Dim>
std::unique_ptr<cosim::SnapshotSink> DecomposedRun<Dim>::snapshots(
    const std::filesystem::path& directory, const std::string& base_name,
    const cosim::Mesh& cells) {
  return std::make_unique<cosim::PartitionedSnapshotWriter>(comm_, directory, base_name, cells,
                                                            block_.link->halo().block().cells);
}

template <int Dim>
const cosim::SnapshotFields& DecomposedRun<Dim>::owned(const cosim::SnapshotFields& fields) {
  const auto& halo = block_.link->halo();
  const auto& extent = halo.padded_extent();
  const auto& below = halo.ghosts_below();
  const auto& cells = halo.block().cells;
  owned_values_.resize(fields.size());
  owned_fields_.clear();
  std::size_t f = 0;
  for (const auto& [name, field] : fields) {
    const auto components = static_cast<std::size_t>(field.components);
    std::vector<double>& values = owned_values_[f++];
    values.clear();
    for (std::int64_t k = 0; k < cells[2].size(); ++k)
      for (std::int64_t j = 0; j < cells[1].size(); ++j) {
        const auto row = static_cast<std::size_t>(
            ((k + below[2]) * extent[1] + j + below[1]) * extent[0] + below[0]);
        const auto first = field.values.begin() + static_cast<std::ptrdiff_t>(row * components);
        values.insert(values.end(), first,
                      first + static_cast<std::ptrdiff_t>(
                                  static_cast<std::size_t>(cells[0].size()) * components));
      }
    owned_fields_.emplace(name, cosim::FieldView{values, field.components, field.unit});
  }
  return owned_fields_;
}

template <int Dim>
std::unique_ptr<PressureSystemSolver<Dim>> petsc_pressure_on_one_process(const CaseDescription& c) {
  const CellGrid<Dim> grid = case_grid<Dim>(c);
  std::array<std::int64_t, 3> cells{1, 1, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) cells[d] = grid.cells()[d];
  const cosim::decomposition::CartesianDecomposition whole(Dim, cells, {1, 1, 1});
  try {
    return std::make_unique<PetscPressureSolver<Dim>>(
        MPI_COMM_SELF, whole, grid, IceSolver<Dim>::pressure_boundaries(case_sides<Dim>(c)), grid,
        typename PetscPressureSolver<Dim>::Offset{}, petsc_pressure_options(c));
  } catch (const PetscOptionsRefused& e) {
    throw refused_options(c, e);
  }
}

template class DecomposedRun<1>;
template class DecomposedRun<2>;
template class DecomposedRun<3>;
template std::unique_ptr<PressureSystemSolver<1>> petsc_pressure_on_one_process<1>(
    const CaseDescription&);
template std::unique_ptr<PressureSystemSolver<2>> petsc_pressure_on_one_process<2>(
    const CaseDescription&);
template std::unique_ptr<PressureSystemSolver<3>> petsc_pressure_on_one_process<3>(
    const CaseDescription&);

}  // namespace ice::parallel

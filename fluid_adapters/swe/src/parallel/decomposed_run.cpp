#include "swe/parallel/decomposed_run.hpp"

#include <fmt/format.h>

#include <string>

#include "cosim/error.hpp"
#include "cosim/io/partitioned_snapshot_writer.hpp"

namespace swe::parallel {

namespace {

cosim::decomposition::CartesianDecomposition decompose_case(MPI_Comm comm,
                                                            const CaseDescription& c) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const std::string where = c.file.string();
  if (c.dimension != 2)
    throw cosim::InputError(
        fmt::format("{}: key 'dimension': a 1D case runs on one rank; mpirun started {} (a "
                    "decomposed run splits a 2D grid)",
                    where, ranks));
  if (c.two_phase)
    throw cosim::InputError(
        fmt::format("{}: key 'two_phase': the two-phase mode runs on one rank; mpirun started {}",
                    where, ranks));
  try {
    return decompose_grid(c.grid, ranks);
  } catch (const cosim::InputError& e) {
    throw cosim::InputError(fmt::format("{}: key 'mesh.cells': {}", where, e.what()));
  }
}

}  // namespace

DecomposedRun::DecomposedRun(MPI_Comm comm, const CaseDescription& description)
    : comm_(comm),
      grid_(description.grid),
      decomposition_(decompose_case(comm, description)),
      link_(std::make_shared<MpiSubdomainLink>(comm, decomposition_)) {
  const auto& b = link_->halo().block();
  const GridBlock block{{static_cast<int>(b.cells[0].begin), static_cast<int>(b.cells[1].begin)},
                        {static_cast<int>(b.cells[0].size()), static_cast<int>(b.cells[1].size())},
                        link_};
  solver_ = make_block_solver(description, block);
}

std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> DecomposedRun::coupling_cells(
    const std::string& mesh_name) const {
  cosim::Mesh whole{mesh_name, cell_mesh(grid_)};
  const auto& b = block();
  cosim::MeshPart part = cosim::MeshPart::box(std::get<cosim::UniformGrid>(whole.geometry),
                                              {b.cells[0].begin, b.cells[1].begin, 0},
                                              {b.cells[0].end, b.cells[1].end, 1});
  return std::make_pair(std::move(whole), std::move(part));
}

bool DecomposedRun::any(bool local) const {
  int flag = local ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_MAX, comm_);
  return flag != 0;
}

void DecomposedRun::sum(std::span<double> values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
}

void DecomposedRun::max(std::span<double> values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                comm_);
}

std::size_t DecomposedRun::cell_at(const Solver& solver, double x, double y) const {
  // The whole grid's cell, so that a point on a face between blocks has one owner.
  const std::size_t whole = swe::cell_at(grid_, x, y);
  const auto nx = static_cast<std::size_t>(grid_.cells[0]);
  const auto ny = static_cast<std::size_t>(grid_.cells[1]);
  if (whole >= nx * ny) return solver.cell_count();
  const auto i = static_cast<std::int64_t>(whole % nx), j = static_cast<std::int64_t>(whole / nx);
  const auto& b = block();
  if (i < b.cells[0].begin || i >= b.cells[0].end || j < b.cells[1].begin || j >= b.cells[1].end)
    return solver.cell_count();
  return static_cast<std::size_t>((i - b.cells[0].begin) +
                                  b.cells[0].size() * (j - b.cells[1].begin));
}

std::unique_ptr<cosim::SnapshotSink> DecomposedRun::snapshots(
    const std::filesystem::path& directory, const std::string& base_name,
    const cosim::Mesh& cells) const {
  return std::make_unique<cosim::PartitionedSnapshotWriter>(
      comm_, directory, base_name, cosim::Mesh{cells.name, cell_mesh(grid_)}, block().cells);
}

}  // namespace swe::parallel

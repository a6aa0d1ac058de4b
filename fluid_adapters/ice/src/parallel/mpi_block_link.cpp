#include "ice/parallel/mpi_block_link.hpp"

#include <algorithm>
#include <vector>

#include "ice/case/make_solver.hpp"

namespace ice::parallel {

namespace {

std::array<std::int64_t, 3> whole_cells(const CaseDescription& c) {
  std::array<std::int64_t, 3> cells{1, 1, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(c.dimension); ++d) cells[d] = c.cells[d];
  return cells;
}

// The values of `whole` (one per cell of `grid`) in the cells of `block`, a
// box of `grid` from `offset`.
template <int Dim, class T>
std::vector<T> part(const std::vector<T>& whole, const CellGrid<Dim>& grid,
                    const CellGrid<Dim>& block,
                    const std::array<int, static_cast<std::size_t>(Dim)>& offset) {
  std::vector<T> values(static_cast<std::size_t>(block.cell_count()));
  for (int c = 0; c < block.cell_count(); ++c) {
    auto ijk = block.cell_ijk(c);
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) ijk[d] += offset[d];
    values[static_cast<std::size_t>(c)] = whole[static_cast<std::size_t>(grid.cell(ijk))];
  }
  return values;
}

}  // namespace

template <int Dim>
MpiBlockLink<Dim>::MpiBlockLink(MPI_Comm comm,
                                const cosim::decomposition::CartesianDecomposition& decomposition,
                                int ghosts)
    : comm_(comm),
      halo_(comm, decomposition, ghosts, cosim::decomposition::GhostSides::toward_neighbours) {}

template <int Dim>
MpiBlockLink<Dim>::~MpiBlockLink() = default;

template <int Dim>
std::array<typename BlockLink<Dim>::Range, static_cast<std::size_t>(Dim)>
MpiBlockLink<Dim>::owned_cells() const {
  std::array<typename BlockLink<Dim>::Range, static_cast<std::size_t>(Dim)> owned{};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    const auto below = static_cast<int>(halo_.ghosts_below()[d]);
    owned[d] = {below, below + static_cast<int>(halo_.block().cells[d].size())};
  }
  return owned;
}

template <int Dim>
void MpiBlockLink<Dim>::fill_ghosts(std::span<const std::span<double>> fields) {
  const double start = MPI_Wtime();
  halo_.exchange(fields);
  values_sent_ += halo_.values_sent();
  seconds_ += MPI_Wtime() - start;
}

template <int Dim>
double MpiBlockLink<Dim>::max(double local) {
  const double start = MPI_Wtime();
  double result = local;
  MPI_Allreduce(&local, &result, 1, MPI_DOUBLE, MPI_MAX, comm_);
  seconds_ += MPI_Wtime() - start;
  return result;
}

template <int Dim>
void MpiBlockLink<Dim>::sum(std::span<double> values) {
  const double start = MPI_Wtime();
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  seconds_ += MPI_Wtime() - start;
}

template <int Dim>
std::array<int, static_cast<std::size_t>(Dim)> MpiBlockLink<Dim>::offset() const {
  std::array<int, static_cast<std::size_t>(Dim)> first{};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
    first[d] = static_cast<int>(halo_.block().cells[d].begin - halo_.ghosts_below()[d]);
  return first;
}

template <int Dim>
CellGrid<Dim> MpiBlockLink<Dim>::block_grid(const CellGrid<Dim>& whole) const {
  typename CellGrid<Dim>::Point origin = whole.origin();
  typename CellGrid<Dim>::CellIndex cells{};
  const auto first = offset();
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    origin[static_cast<int>(d)] += first[d] * whole.spacing()[static_cast<int>(d)];
    cells[d] = static_cast<int>(halo_.padded_extent()[d]);
  }
  return CellGrid<Dim>(origin, whole.spacing(), cells);
}

template <int Dim>
BlockSolver<Dim> make_block_solver(MPI_Comm comm, const CaseDescription& c,
                                   const PetscPressureOptions& pressure, int ghosts) {
  const CellGrid<Dim> grid = case_grid<Dim>(c);
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const auto cells = whole_cells(c);
  const auto dims =
      cosim::decomposition::process_grid(ranks, std::span<const std::int64_t>(cells.data(), Dim));
  cosim::decomposition::CartesianDecomposition decomposition(Dim, cells, dims);
  auto link = std::make_shared<MpiBlockLink<Dim>>(comm, decomposition, ghosts);
  const CellGrid<Dim> block = link->block_grid(grid);
  const auto offset = link->offset();

  // The block's columns alone are filled (whole along gravity for the
  // hydrostatic pressure), not the whole grid.
  const auto [first, count] = fill_box_along_gravity<Dim>(c, grid, offset, block.cells());
  const CellFill<Dim> columns = case_fill<Dim>(c, grid, first, count);
  const CellGrid<Dim> box(grid.origin(), grid.spacing(), count);
  auto in_box = offset;
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) in_box[d] -= first[d];
  CellFill<Dim> fill;
  fill.material = part<Dim>(columns.material, box, block, in_box);
  fill.pressure = part<Dim>(columns.pressure, box, block, in_box);
  fill.temperature = part<Dim>(columns.temperature, box, block, in_box);
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
    fill.velocity[d] = part<Dim>(columns.velocity[d], box, block, in_box);

  // Toward a neighbour the widened edge is a wall: what it spoils stays in the ghosts.
  typename IceSolver<Dim>::Sides sides = case_sides<Dim>(c);
  for (std::size_t s = 0; s < sides.size(); ++s)
    if (link->halo().block().neighbour[s] >= 0) sides[s] = SideCondition{};

  const IceSolverOptions options = case_solver_options(c);
  auto solver = std::make_unique<IceSolver<Dim>>(
      block, c.materials, c.exchange, sides, case_gravity<Dim>(c),
      make_initial_state(block, c.materials, fill, c.initial.minimum_volume_fraction), options);
  auto petsc = std::make_unique<PetscPressureSolver<Dim>>(
      comm, decomposition, grid, IceSolver<Dim>::pressure_boundaries(case_sides<Dim>(c)), block,
      offset, pressure);
  solver->link_blocks(link, std::move(petsc));
  return {std::move(solver), std::move(link), decomposition};
}

template class MpiBlockLink<1>;
template class MpiBlockLink<2>;
template class MpiBlockLink<3>;
template BlockSolver<1> make_block_solver<1>(MPI_Comm, const CaseDescription&,
                                             const PetscPressureOptions&, int);
template BlockSolver<2> make_block_solver<2>(MPI_Comm, const CaseDescription&,
                                             const PetscPressureOptions&, int);
template BlockSolver<3> make_block_solver<3>(MPI_Comm, const CaseDescription&,
                                             const PetscPressureOptions&, int);

}  // namespace ice::parallel

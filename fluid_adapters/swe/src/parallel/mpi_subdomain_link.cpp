#include "swe/parallel/mpi_subdomain_link.hpp"

#include <fmt/format.h>

#include <array>
#include <utility>

#include "cosim/error.hpp"

namespace swe::parallel {

namespace {

// The blocks' ghost layers: the stencil of the MUSCL reconstruction.
constexpr int ghost_layers = 2;

}  // namespace

MpiSubdomainLink::MpiSubdomainLink(
    MPI_Comm comm, const cosim::decomposition::CartesianDecomposition& decomposition)
    : halo_(comm, decomposition, ghost_layers) {
  MPI_Comm_dup(comm, &comm_);
}

MpiSubdomainLink::~MpiSubdomainLink() {
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

std::array<bool, 4> MpiSubdomainLink::linked_sides() const {
  const auto& n = halo_.block().neighbour;
  return {n[0] >= 0, n[1] >= 0, n[2] >= 0, n[3] >= 0};
}

void MpiSubdomainLink::fill_ghosts(std::span<const std::span<double>> arrays) {
  const double start = MPI_Wtime();
  halo_.exchange(arrays);
  values_sent_ += halo_.values_sent();
  seconds_ += MPI_Wtime() - start;
}

double MpiSubdomainLink::max(double local) {
  const double start = MPI_Wtime();
  double global = local;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_);
  seconds_ += MPI_Wtime() - start;
  return global;
}

void MpiSubdomainLink::sum(std::span<double> values) {
  const double start = MPI_Wtime();
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  seconds_ += MPI_Wtime() - start;
}

Grid2d block_grid(const Grid2d& grid, const cosim::decomposition::Block& block) {
  return sub_grid(
      grid, {static_cast<int>(block.cells[0].begin), static_cast<int>(block.cells[1].begin)},
      {static_cast<int>(block.cells[0].size()), static_cast<int>(block.cells[1].size())});
}

cosim::decomposition::CartesianDecomposition decompose_grid(const Grid2d& grid, int ranks) {
  const std::array<std::int64_t, 2> cells{grid.cells[0], grid.cells[1]};
  const std::array<int, 3> dims = cosim::decomposition::process_grid(ranks, cells);
  for (std::size_t d = 0; d < 2; ++d)
    if (dims[d] > 1 && cells[d] < ghost_layers * dims[d])
      throw cosim::InputError(fmt::format(
          "{} ranks split the grid's {} cells in {} into {} parts, fewer than {} cells each: "
          "run on fewer ranks",
          ranks, cells[d], d == 0 ? "x" : "y", dims[d], ghost_layers));
  return {2, {cells[0], cells[1], 1}, dims};
}

BlockSolver2d make_block_solver(MPI_Comm comm, const Grid2d& grid, const Physics& physics,
                                const Scheme& scheme, const Boundaries2d& boundaries) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  auto link = std::make_shared<MpiSubdomainLink>(comm, decompose_grid(grid, ranks));
  BlockSolver2d part{nullptr, link, link->halo().block()};
  part.solver =
      std::make_unique<Solver2d>(block_grid(grid, part.block), physics, scheme, boundaries, link);
  return part;
}

}  // namespace swe::parallel

// The 2D shallow-water solver decomposed over 1 to 4 ranks (mpirun, label
// mpi): every rank also runs the whole grid on its own, and its block must
// hold, bit for bit, the same cells after every step, with the same time
// steps; the totals reduced over the ranks agree with the whole grid's to
// round-off.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "cosim/error.hpp"
#include "swe/parallel/mpi_subdomain_link.hpp"
#include "swe/solver_2d.hpp"

namespace swe {
namespace {

int world_size() {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}

// A dam break over a bump, partly onto dry ground, with Manning friction and
// one boundary of each kind, so that fronts, dry cells and every ghost rule
// cross the blocks' edges.
struct DamBreakOverABump {
  Grid2d grid{{-1.0, 2.0}, {0.25, 0.2}, {41, 27}};
  Physics physics{.gravity = 9.81, .density = 1000.0, .manning = 0.02, .dry_depth = 1e-6};
  Scheme scheme{};
  Boundaries2d boundaries{.x_min = {BoundaryKind::wall, 0.0},
                          .x_max = {BoundaryKind::transmissive, 0.0},
                          .y_min = {BoundaryKind::inflow_discharge, 0.3},
                          .y_max = {BoundaryKind::fixed_depth, 0.4}};
  std::vector<double> bed, h, hu, hv;

  DamBreakOverABump() {
    const auto n = static_cast<std::size_t>(grid.cells[0] * grid.cells[1]);
    bed.resize(n);
    h.resize(n);
    hu.resize(n);
    hv.resize(n);
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const auto c = static_cast<std::size_t>(i + grid.cells[0] * j);
        const double x = (i + 0.5) / grid.cells[0], y = (j + 0.5) / grid.cells[1];
        bed[c] = 0.3 * std::exp(-40.0 * ((x - 0.6) * (x - 0.6) + (y - 0.4) * (y - 0.4)));
        h[c] = x < 0.35 + 0.1 * y ? std::max(0.0, 1.0 - bed[c]) : (y > 0.8 ? 0.05 : 0.0);
        hu[c] = 0.1 * h[c] * y;
        hv[c] = -0.05 * h[c] * x;
      }
  }

  // The values of `whole` in the block's cells, x fastest.
  std::vector<double> part(const std::vector<double>& whole,
                           const cosim::decomposition::Block& b) const {
    std::vector<double> values;
    for (auto j = b.cells[1].begin; j < b.cells[1].end; ++j)
      for (auto i = b.cells[0].begin; i < b.cells[0].end; ++i)
        values.push_back(whole[static_cast<std::size_t>(i + grid.cells[0] * j)]);
    return values;
  }
};

// Cells of the block that differ in any bit from the whole grid's.
int differing_cells(std::span<const double> block, std::span<const double> whole,
                    const DamBreakOverABump& problem, const cosim::decomposition::Block& b) {
  const std::vector<double> expected =
      problem.part(std::vector<double>(whole.begin(), whole.end()), b);
  int differing = 0;
  for (std::size_t c = 0; c < expected.size(); ++c)
    if (std::memcmp(&block[c], &expected[c], sizeof(double)) != 0) ++differing;
  return differing;
}

TEST(Swe2dDecomposed, EveryBlockMatchesTheWholeGridBitForBit) {
  const DamBreakOverABump problem;
  Solver2d whole(problem.grid, problem.physics, problem.scheme, problem.boundaries);
  whole.set_bed(problem.bed);
  whole.set_state(problem.h, problem.hu, problem.hv);
  parallel::BlockSolver2d part = parallel::make_block_solver(
      MPI_COMM_WORLD, problem.grid, problem.physics, problem.scheme, problem.boundaries);
  const auto& b = part.block;
  part.solver->set_bed(problem.part(problem.bed, b));
  part.solver->set_state(problem.part(problem.h, b), problem.part(problem.hu, b),
                         problem.part(problem.hv, b));
  const Totals start = whole.totals();
  for (int step = 0; step < 80; ++step) {
    const double dt = whole.stable_time_step();
    ASSERT_EQ(part.solver->stable_time_step(), dt) << "step " << step;
    whole.step(dt);
    part.solver->step(dt);
    const int differing =
        differing_cells(part.solver->depth(), whole.depth(), problem, b) +
        differing_cells(part.solver->discharge_x(), whole.discharge_x(), problem, b) +
        differing_cells(part.solver->discharge_y(), whole.discharge_y(), problem, b);
    ASSERT_EQ(differing, 0) << "step " << step << ", rank " << part.link->halo().rank() << " of "
                            << world_size();
  }
  const Totals end = whole.totals(), reduced = part.solver->totals();
  EXPECT_NE(end.volume, start.volume);  // water came in and left: the boundaries acted
  EXPECT_NEAR(reduced.volume, end.volume, 1e-13 * end.volume);
  EXPECT_NEAR(reduced.momentum_x, end.momentum_x, 1e-13 * end.volume);
  EXPECT_NEAR(reduced.momentum_y, end.momentum_y, 1e-13 * end.volume);
  if (part.link->halo().rank() == 0)
    std::printf("%d ranks: 80 steps bit-identical; volume %.17g (whole grid %.17g)\n", world_size(),
                reduced.volume, end.volume);
}

// A 3 x 3 grid cannot be split into blocks of two cells; on one rank it is whole.
TEST(Swe2dDecomposed, RefusesBlocksNarrowerThanTheGhostLayers) {
  const DamBreakOverABump problem;
  Grid2d narrow = problem.grid;
  narrow.cells = {3, 3};
  auto split = [&] {
    return parallel::make_block_solver(MPI_COMM_WORLD, narrow, problem.physics, problem.scheme,
                                       problem.boundaries);
  };
  if (world_size() == 1)
    EXPECT_EQ(split().solver->cell_count(), 9u);
  else
    EXPECT_THROW(split(), cosim::InputError);
}

}  // namespace
}  // namespace swe

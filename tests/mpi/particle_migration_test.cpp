// Material points migrating between the blocks of a decomposed grid, on 1
// to 4 ranks (mpirun, label mpi): a block of points that starts wholly in
// rank 0's block (the others empty) translates across the grid, a fraction
// of a cell per step, and after every step each point sits on the rank that
// owns its cell, none is lost or doubled, and every array of its state
// arrives intact.
#include "mpm/parallel/particle_migration.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace mpm::parallel {
namespace {

namespace dc = cosim::decomposition;

// The state of point `id`, different in every array, so that a point that
// mixed up two arrays or two points would show.
template <int Dim>
void set_state(Particles<Dim>& p, std::size_t i, std::size_t id) {
  const double x = static_cast<double>(id);
  p.velocity[i].setConstant(x + 0.5);
  p.deformation_gradient[i].setConstant(x + 0.25);
  p.half_length[i].setConstant(x + 0.75);
  p.mass[i] = x + 1.0;
  p.initial_volume[i] = x;  // the id
  p.volume[i] = x + 2.0;
  p.stress[i] = {x, -x, 2 * x, 3 * x, 4 * x, 5 * x};
  p.plastic_strain[i] = x + 3.0;
  p.damage[i] = x + 4.0;
  p.internal[i] = {x + 5.0, x + 6.0};
  p.porosity[i] = x + 7.0;
  p.initial_porosity[i] = x + 8.0;
  p.permeability[i] = x + 9.0;
  p.grain_size[i] = x + 10.0;
  p.pore_pressure[i] = x + 11.0;
  p.temperature[i] = x + 12.0;
  p.temperature_gradient[i].setConstant(x + 13.0);
  p.heat_capacity[i] = x + 14.0;
  p.external_force[i].setConstant(x + 15.0);
  p.external_heat[i] = x + 16.0;
  p.body[i] = static_cast<std::uint32_t>(id % 7);
  p.id[i] = id;
}

// Whether every array of point i is that of its id (initial_volume).
template <int Dim>
bool state_intact(const Particles<Dim>& p, std::size_t i) {
  Particles<Dim> expected;
  expected.resize(1);
  expected.position[0] = p.position[i];
  set_state(expected, 0, static_cast<std::size_t>(p.initial_volume[i]));
  bool same = true;
  std::size_t array = 0;
  expected.for_each_array([&](const auto& values) {
    std::size_t k = 0;
    p.for_each_array([&](const auto& mine) {
      if (k++ == array) same = same && std::memcmp(&mine[i], &values[0], sizeof(values[0])) == 0;
    });
    ++array;
  });
  return same;
}

template <int Dim>
void translate_a_block_across_the_ranks() {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::array<std::int64_t, 3> cells{16, 12, Dim == 3 ? 10 : 1};
  const auto dims = dc::process_grid(ranks, std::span<const std::int64_t>(cells.data(), Dim));
  const dc::CartesianDecomposition decomposition(Dim, cells, dims);
  const double h = 0.5;
  ParticleMigration<Dim> migration(MPI_COMM_WORLD, decomposition, Vec<Dim>::Zero(), h);

  // 4 points per cell in 4 x 3 (x 2) cells at the grid's origin, all on rank 0.
  Particles<Dim> p;
  std::size_t total = 0;
  if (rank == 0) {
    const int per_side[3] = {8, 6, Dim == 3 ? 4 : 1};
    p.resize(static_cast<std::size_t>(per_side[0] * per_side[1] * per_side[2]));
    for (int k = 0; k < per_side[2]; ++k)
      for (int j = 0; j < per_side[1]; ++j)
        for (int i = 0; i < per_side[0]; ++i) {
          const std::size_t id = static_cast<std::size_t>(i + per_side[0] * (j + per_side[1] * k));
          const int index[3] = {i, j, k};
          for (int d = 0; d < Dim; ++d) p.position[id][d] = (index[d] + 0.5) * 0.5 * h;
          set_state(p, id, id);
        }
    total = p.size();
  }
  MPI_Bcast(&total, 1, MPI_UNSIGNED_LONG, 0, MPI_COMM_WORLD);
  Vec<Dim> step;
  step.setConstant(0.3 * h);
  step[0] = 0.45 * h;
  std::size_t moved_total = 0;
  for (int s = 0; s < 40; ++s) {
    for (auto& x : p.position) x += step;
    const auto moved = migration.migrate(p);
    moved_total += moved.sent;
    unsigned long held = p.size();
    MPI_Allreduce(MPI_IN_PLACE, &held, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
    ASSERT_EQ(held, total) << "step " << s;
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_EQ(migration.owner(p.position[i]), rank) << "step " << s;
      ASSERT_TRUE(state_intact(p, i)) << "point " << p.initial_volume[i] << ", step " << s;
    }
  }
  // Every id exactly once over the ranks.
  std::vector<int> seen(total, 0);
  for (const double id : p.initial_volume) ++seen[static_cast<std::size_t>(id)];
  MPI_Allreduce(MPI_IN_PLACE, seen.data(), static_cast<int>(total), MPI_INT, MPI_SUM,
                MPI_COMM_WORLD);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  MPI_Allreduce(MPI_IN_PLACE, &moved_total, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
  // Every point ends in the far corner: on several ranks it crossed at least
  // one cut; on one it never moves.
  if (ranks > 1) {
    EXPECT_GE(moved_total, total);
  } else {
    EXPECT_EQ(moved_total, 0u);
  }
}

TEST(ParticleMigration, ABlockCrossingTheRanksKeepsEveryPointAndItsStateIn2D) {
  translate_a_block_across_the_ranks<2>();
}

TEST(ParticleMigration, ABlockCrossingTheRanksKeepsEveryPointAndItsStateIn3D) {
  translate_a_block_across_the_ranks<3>();
}

}  // namespace
}  // namespace mpm::parallel

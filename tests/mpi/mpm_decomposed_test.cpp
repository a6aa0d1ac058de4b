// The MPM solver decomposed over 1 to 4 ranks (mpirun, label mpi): every
// rank also runs the whole case on its own, and after every step each point
// it holds must carry, bit for bit, the whole run's state of the point with
// its id, with the same time step; no point is lost or doubled; the totals
// summed over the ranks agree with the whole run's to round-off.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "cosim/error.hpp"
#include "mpm/parallel/mpi_grid_partition.hpp"
#include "mpm/solver/solver.hpp"
#include "mpm_case_builder.hpp"

namespace mpm {
namespace {

using testing::box_body;
using testing::elastic;
using testing::empty_case;
using testing::material_from_yaml;

int world_size() {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}

std::shared_ptr<const Material> sand() {
  return material_from_yaml(
      "type: mohr_coulomb\ndensity: 1800\nyoungs_modulus: 2e6\npoisson_ratio: 0.3\n"
      "friction_angle: 30\ncohesion: 200\n");
}

// The index of the first array in which point p of `part` differs from
// point `id` of `whole`, or -1.
template <int Dim>
int first_difference(const Particles<Dim>& part, std::size_t p, const Particles<Dim>& whole,
                     std::size_t id) {
  std::vector<const void*> mine, theirs;
  std::vector<std::size_t> sizes;
  part.for_each_array([&](const auto& a) {
    mine.push_back(&a[p]);
    sizes.push_back(sizeof(a[p]));
  });
  whole.for_each_array([&](const auto& a) { theirs.push_back(&a[id]); });
  for (std::size_t k = 0; k < mine.size(); ++k)
    if (std::memcmp(mine[k], theirs[k], sizes[k]) != 0) return static_cast<int>(k);
  return -1;
}

// The cuts moved by one slab: each interior cut up a slab where the parts
// keep one, else down.
std::vector<int> shifted(std::vector<int> cuts) {
  for (std::size_t k = 1; k + 1 < cuts.size(); ++k) {
    if (cuts[k] + 4 < cuts[k + 1])
      cuts[k] += 4;
    else if (cuts[k] - 4 > cuts[k - 1])
      cuts[k] -= 4;
  }
  return cuts;
}

// `recut_every` > 0: every so many steps the cuts move (alternately by a
// slab, and to the balance of the points where they are then) and the
// solver repartitions.
template <int Dim>
void expect_the_whole_runs_bits(const CaseDescription& c, int steps, int recut_every = 0) {
  const int ranks = world_size();
  Solver<Dim> whole(c);
  const auto cuts = parallel::balanced_row_cuts(c, ranks);
  auto partition = std::make_shared<parallel::MpiGridPartition<Dim>>(
      MPI_COMM_WORLD, cuts, c.grid.origin[Dim - 1], c.grid.spacing[Dim - 1]);
  Solver<Dim> part(c, partition);
  for (int s = 0; s < steps; ++s) {
    const double dt = whole.stable_time_step();
    const double dt_part = part.stable_time_step();
    ASSERT_EQ(std::memcmp(&dt, &dt_part, sizeof dt), 0) << "step " << s;
    whole.step(dt);
    part.step(dt);
    if (recut_every > 0 && (s + 1) % recut_every == 0) {
      if ((s + 1) / recut_every % 2 == 1) {
        partition->recut(shifted(partition->cuts()));
        part.repartition();
      } else if (partition->rebalance(part.particles(), 1.0)) {
        part.repartition();
      }
    }
    const Particles<Dim>& mine = part.particles();
    unsigned long held = mine.size();
    MPI_Allreduce(MPI_IN_PLACE, &held, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
    ASSERT_EQ(held, whole.particles().size()) << "step " << s;
    int differing = 0;
    for (std::size_t p = 0; p < mine.size(); ++p) {
      const std::size_t id = mine.id[p];
      ASSERT_LT(id, whole.particles().size());
      EXPECT_EQ(partition->owner(mine.position[p]), partition->rank());
      const int array = first_difference(mine, p, whole.particles(), id);
      if (array >= 0 && differing++ < 3)
        ADD_FAILURE() << "step " << s << ": point " << id << " differs in array " << array;
    }
    MPI_Allreduce(MPI_IN_PLACE, &differing, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    ASSERT_EQ(differing, 0) << "points that differ after step " << s;
  }
  unsigned long migrated = partition->points_sent();
  // Every id held once.
  std::vector<int> seen(whole.particles().size(), 0);
  for (const auto id : part.particles().id) ++seen[id];
  MPI_Allreduce(MPI_IN_PLACE, seen.data(), static_cast<int>(seen.size()), MPI_INT, MPI_SUM,
                MPI_COMM_WORLD);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  MPI_Allreduce(MPI_IN_PLACE, &migrated, 1, MPI_UNSIGNED_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (ranks > 1) {
    EXPECT_GT(migrated, 0u) << "no point crossed a cut: the test tests nothing";
  }

  const Totals<Dim> a = whole.totals(), b = part.totals();
  const auto close = [](double x, double y, double scale) {
    return std::abs(x - y) <= 1e-12 * std::max(1.0, scale);
  };
  EXPECT_TRUE(close(a.mass, b.mass, a.mass)) << a.mass << " vs " << b.mass;
  for (int d = 0; d < Dim; ++d)
    EXPECT_TRUE(close(a.momentum[d], b.momentum[d], a.mass))
        << a.momentum[d] << " vs " << b.momentum[d];
  const double energy = a.kinetic_energy + std::abs(a.gravitational_energy) + a.strain_energy;
  EXPECT_TRUE(close(a.kinetic_energy, b.kinetic_energy, energy));
  EXPECT_TRUE(close(a.strain_energy, b.strain_energy, energy));
  EXPECT_TRUE(close(a.internal_work, b.internal_work, energy));
  EXPECT_TRUE(close(a.contact_dissipation, b.contact_dissipation, energy));
  EXPECT_TRUE(close(a.boundary_dissipation, b.boundary_dissipation, energy));
  EXPECT_TRUE(close(a.external_work, b.external_work, energy));
  const double heat = std::abs(a.thermal_energy);
  EXPECT_TRUE(close(a.thermal_energy, b.thermal_energy, heat))
      << a.thermal_energy << " vs " << b.thermal_energy;
  EXPECT_TRUE(close(a.heat_through_faces, b.heat_through_faces, heat))
      << a.heat_through_faces << " vs " << b.heat_through_faces;
  EXPECT_TRUE(close(a.external_heat, b.external_heat, heat));
  if (c.thermal.enabled) {
    EXPECT_GT(std::abs(a.heat_through_faces), 0.0) << "no heat moved";
  }
}

// Two blocks, elastic and Mohr-Coulomb, thrown down onto a fixed floor and
// into each other between slip walls: GIMP, MUSL, F-bar, friction contact
// between the bodies, frictional floor; the points cross the cuts.
TEST(MpmDecomposed, TwoBodiesInContactFallingAcrossTheCutsIn2D) {
  CaseDescription c = empty_case(2, {12, 40, 1}, 0.05);
  c.materials = {elastic(1000.0, 1e6, 0.3), sand()};
  c.bodies.push_back(
      box_body("elastic", 0, 2, Vec3d(0.1, 0.5, 0.0), Vec3d(0.3, 1.6, 0.0), 0.05, 2));
  c.bodies.push_back(box_body("sand", 1, 2, Vec3d(0.3, 0.2, 0.0), Vec3d(0.55, 1.1, 0.0), 0.05, 2));
  c.bodies[0].initial_velocity = Vec3d(0.4, -6.0, 0.0);
  c.bodies[1].initial_velocity = Vec3d(-0.2, -3.0, 0.0);
  c.gravity = Vec3d(0.0, -9.81, 0.0);
  c.contact.enabled = true;
  c.contact.friction = 0.3;
  c.locking = LockingMitigation::fbar;
  c.boundaries[0].kind = FaceCondition::Kind::slip;
  c.boundaries[1].kind = FaceCondition::Kind::slip;
  c.boundaries[2] = {FaceCondition::Kind::frictional, 0.4};
  expect_the_whole_runs_bits<2>(c, 120);
}

// A free rigid box thrown down along the side of a tall elastic column and
// into it, so that they touch over several ranks' rows: quadratic
// B-splines, USL, and the contact impulse on the rigid body summed over the
// ranks in a fixed order.
TEST(MpmDecomposed, ARigidBodySlidingAlongAColumnIn3D) {
  CaseDescription c = empty_case(3, {6, 5, 24}, 0.1);
  c.shape = ShapeKind::quadratic_bspline;
  c.scheme = UpdateScheme::usl;
  c.materials = {elastic(1000.0, 2e5, 0.25)};
  c.bodies.push_back(box_body("column", 0, 3, Vec3d(0.1, 0.1, 0.0), Vec3d(0.3, 0.4, 2.0), 0.1, 2));
  BodySpec box = box_body("box", -1, 3, Vec3d(0.3, 0.1, 0.8), Vec3d(0.5, 0.4, 1.8), 0.1, 2);
  box.rigid = RigidMotion{RigidMotion::Kind::free, {}};
  box.density_override = 2000.0;
  box.initial_velocity = Vec3d(-1.0, 0.0, -2.0);
  c.bodies.push_back(box);
  c.gravity = Vec3d(0.0, 0.0, -9.81);
  c.contact.enabled = true;
  c.contact.friction = 0.2;
  for (int f = 0; f < 5; ++f)
    c.boundaries[static_cast<std::size_t>(f)].kind = FaceCondition::Kind::slip;
  expect_the_whole_runs_bits<3>(c, 80);
}

// A column pressed by a surface load on its top points, linear shape
// functions, one velocity field, PIC-FLIP blend.
TEST(MpmDecomposed, AColumnUnderASurfaceLoadIn2D) {
  CaseDescription c = empty_case(2, {4, 32, 1}, 0.05);
  c.shape = ShapeKind::linear;
  c.flip_fraction = 0.5;
  c.materials = {elastic(1500.0, 5e5, 0.2)};
  c.bodies.push_back(box_body("column", 0, 2, Vec3d(0.0, 0.0, 0.0), Vec3d(0.2, 1.5, 0.0), 0.05, 2));
  LoadSpec load;
  load.name = "top";
  const auto& positions = c.bodies[0].positions;
  for (std::size_t p = 0; p < positions.size(); ++p)
    if (positions[p][1] > 1.48) load.particles.push_back(p);
  load.pressure = 4e4;
  load.ramp_time = 0.01;
  c.loads.push_back(load);
  c.boundaries[0].kind = FaceCondition::Kind::slip;
  c.boundaries[1].kind = FaceCondition::Kind::slip;
  c.boundaries[2].kind = FaceCondition::Kind::fixed;
  expect_the_whole_runs_bits<2>(c, 150);
}

// The column again, its cuts moved every 7 steps: repartitioning keeps every
// point's bits, and the balance of the points is restored.
TEST(MpmDecomposed, MovingTheCutsKeepsTheBits) {
  CaseDescription c = empty_case(2, {4, 32, 1}, 0.05);
  c.shape = ShapeKind::linear;
  c.materials = {elastic(1500.0, 5e5, 0.2)};
  c.bodies.push_back(box_body("column", 0, 2, Vec3d(0.0, 0.0, 0.0), Vec3d(0.2, 1.5, 0.0), 0.05, 2));
  c.bodies[0].initial_velocity = Vec3d(0.0, -2.0, 0.0);
  c.gravity = Vec3d(0.0, -9.81, 0.0);
  c.boundaries[2].kind = FaceCondition::Kind::fixed;
  expect_the_whole_runs_bits<2>(c, 100, 7);
  const auto cuts = parallel::balanced_row_cuts(c, world_size());
  auto partition = std::make_shared<parallel::MpiGridPartition<2>>(MPI_COMM_WORLD, cuts, 0.0, 0.05);
  Solver<2> part(c, partition);
  partition->recut(shifted(cuts));
  part.repartition();
  const double unbalanced = partition->imbalance(part.particles());
  if (partition->rebalance(part.particles(), 1.0)) part.repartition();
  EXPECT_LE(partition->imbalance(part.particles()), unbalanced);
  if (world_size() > 1) {
    EXPECT_GT(unbalanced, 1.0);
    EXPECT_EQ(partition->cuts(), cuts);
  }
}

// The coupling's reductions over the ranks (mpm::coupling on ranks): the
// largest value of each entry, and every rank's values in rank order.
TEST(MpmDecomposed, MaxAndGatherJoinTheRanks) {
  const int ranks = world_size();
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<int> cuts(static_cast<std::size_t>(ranks) + 1);
  for (int r = 0; r <= ranks; ++r) cuts[static_cast<std::size_t>(r)] = 4 * r;
  parallel::MpiGridPartition<2> partition(MPI_COMM_WORLD, cuts, 0.0, 0.05);
  std::vector<double> values{static_cast<double>(rank), -static_cast<double>(rank),
                             -std::numeric_limits<double>::infinity()};
  partition.max(values);
  EXPECT_EQ(values[0], ranks - 1);
  EXPECT_EQ(values[1], 0.0);
  EXPECT_EQ(values[2], -std::numeric_limits<double>::infinity());
  // Rank r gives r values r + 0.5: 0 from rank 0, an empty rank is fine.
  const std::vector<double> mine(static_cast<std::size_t>(rank), rank + 0.5);
  const std::vector<double> all = partition.gather(mine);
  std::vector<double> expected;
  for (int r = 0; r < ranks; ++r)
    expected.insert(expected.end(), static_cast<std::size_t>(r), r + 0.5);
  EXPECT_EQ(all, expected);
}

TEST(MpmDecomposed, MoreRanksThanSlabsIsAnInputError) {
  // One slab fewer than ranks (one slab on one rank).
  CaseDescription c = empty_case(2, {8, 4 * std::max(1, world_size() - 1), 1}, 0.05);
  c.materials = {elastic(1000.0, 1e6, 0.3)};
  c.bodies.push_back(box_body("b", 0, 2, Vec3d(0.1, 0.0, 0.0), Vec3d(0.3, 0.1, 0.0), 0.05, 2));
  if (world_size() == 1) {
    EXPECT_NO_THROW(parallel::balanced_row_cuts(c, 1));
  } else {
    EXPECT_THROW(parallel::balanced_row_cuts(c, world_size()), cosim::InputError);
  }
}

// Heat conduction across the cuts: a hot block on a cold one, falling onto
// a floor held at 350 K, the cuts moving every 7 steps. The temperatures,
// their gradients and the heat through the floor are one process's.
TEST(MpmDecomposed, HeatConductionAcrossTheCutsKeepsTheBits) {
  CaseDescription c = empty_case(2, {8, 24, 1}, 0.05);
  c.shape = ShapeKind::gimp;
  c.materials = {
      material_from_yaml("type: linear_elastic\ndensity: 2000\nyoungs_modulus: "
                         "5.0e5\npoisson_ratio: 0.25\nspecific_heat: 800\n"
                         "thermal_conductivity: 5000\n")};
  c.bodies.push_back(box_body("cold", 0, 2, Vec3d(0.1, 0.0, 0.0), Vec3d(0.3, 0.4, 0.0), 0.05, 2));
  c.bodies.push_back(box_body("hot", 0, 2, Vec3d(0.1, 0.4, 0.0), Vec3d(0.3, 0.8, 0.0), 0.05, 2));
  c.bodies[0].initial_temperature = 300.0;
  c.bodies[1].initial_temperature = 400.0;
  for (auto& body : c.bodies) body.initial_velocity = Vec3d(0.0, -1.5, 0.0);
  c.gravity = Vec3d(0.0, -9.81, 0.0);
  c.boundaries[2].kind = FaceCondition::Kind::fixed;
  c.thermal.enabled = true;
  c.thermal.faces[2] = {FaceTemperature::Kind::fixed, 350.0};
  expect_the_whole_runs_bits<2>(c, 120, 7);
}

}  // namespace
}  // namespace mpm

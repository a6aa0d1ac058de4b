// The water's traction on the bed, applied to the surface particles of each
// column (Zheng et al., eq. 10 and Algorithm 1, line 21).
#include "mpm/coupling/surface_traction.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "particle_fixtures.hpp"

namespace mpm::coupling {
namespace {

TEST(MpmCouplingSurfaceTraction, ColumnForcesSumToTractionTimesArea2D) {
  const Grid<2> g = make_grid<2>(Vec<2>::Zero(), Vec<2>(0.1, 0.1), {10, 10}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<2>::covering(g, {5});
  Particles<2> particles;
  const double d = 0.05;
  testing::add_block<2>(particles, Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.4), d, 0.4, 2650.0, 0);
  testing::add_block<2>(particles, Vec<2>(0.0, 0.4), Vec<2>(0.6, 0.6), d, 0.4, 2650.0,
                        0);  // a step in the bed
  const auto roles = testing::porous_roles();
  std::vector<double> traction(5 * 2);
  for (std::size_t c = 0; c < 5; ++c) {
    traction[2 * c] = 10.0 * (static_cast<double>(c) + 1.0);               // shear
    traction[2 * c + 1] = -9810.0 * (1.0 - 0.1 * static_cast<double>(c));  // hydrostatic, downward
  }
  std::vector<Vec<2>> force;
  const auto totals = surface_traction(surface, traction, particles, roles, force);
  Vec<2> expected = Vec<2>::Zero(), applied = Vec<2>::Zero();
  for (std::size_t c = 0; c < 5; ++c)
    expected += 0.2 * Vec<2>(traction[2 * c], traction[2 * c + 1]);
  for (const auto& f : force) applied += f;
  const double error = (applied - expected).norm() / expected.norm();
  std::printf("  applied vs sum t A: relative error %.2e (tol 1e-12), %zu surface particles\n",
              error, totals.surface_particles);
  EXPECT_LT(error, 1e-12);
  EXPECT_LT((totals.received - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(totals.unapplied.norm(), 0.0);
  // Only the top layer of each column (tops less than one particle height below the highest).
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double top = particles.position[p][1] + particles.half_length[p][1];
    const double column_top = particles.position[p][0] < 0.6 ? 0.6 : 0.4;
    const bool surface_particle = top > column_top - 0.5 * d;  // the top layer, not the one below
    EXPECT_EQ(force[p].norm() > 0.0, surface_particle)
        << p << " at " << particles.position[p].transpose() << " top " << top;
  }
  // Every column's particles carry exactly its force.
  for (std::size_t c = 0; c < 5; ++c) {
    Vec<2> column = Vec<2>::Zero();
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (surface.column_of(particles.position[p]) == c) column += force[p];
    EXPECT_LT((column - 0.2 * Vec<2>(traction[2 * c], traction[2 * c + 1])).norm(), 1e-9) << c;
  }
}

TEST(MpmCouplingSurfaceTraction,
     ColumnForcesSumToTractionTimesArea3DAndEmptyColumnsReportWhatIsLost) {
  const Grid<3> g = make_grid<3>(Vec<3>::Zero(), Vec<3>::Constant(0.1), {6, 4, 4}, ShapeKind::gimp);
  const auto surface = SurfaceGrid<3>::covering(g, {3, 2});
  Particles<3> particles;
  testing::add_block<3>(particles, Vec<3>(0.0, 0.0, 0.0), Vec<3>(0.4, 0.4, 0.2), 0.05, 0.4, 2650.0,
                        0);
  const auto roles = testing::porous_roles();
  std::vector<double> traction(6 * 3);
  for (std::size_t k = 0; k < traction.size(); ++k)
    traction[k] = std::cos(static_cast<double>(k)) * 100.0;
  std::vector<Vec<3>> force;
  const auto totals = surface_traction(surface, traction, particles, roles, force);
  Vec<3> applied = Vec<3>::Zero();
  for (const auto& f : force) applied += f;
  const Vec<3> lost(
      traction[2 * 3] * 0.04 + traction[5 * 3] * 0.04,
      traction[2 * 3 + 1] * 0.04 + traction[5 * 3 + 1] * 0.04,
      traction[2 * 3 + 2] * 0.04 + traction[5 * 3 + 2] * 0.04);  // column x = 2 is empty
  EXPECT_LT((totals.unapplied - lost).norm(), 1e-12);
  EXPECT_LT((applied + totals.unapplied - totals.received).norm(), 1e-12 * totals.received.norm());
  EXPECT_LT((applied - totals.applied).norm(), 1e-12);
}

}  // namespace
}  // namespace mpm::coupling

#include "mpm/solver/solver.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "cosim/error.hpp"
#include "mpm_case_builder.hpp"

namespace mpm {
namespace {

using testing::box_body;
using testing::elastic;
using testing::empty_case;

template <int Dim>
CaseDescription spinning_block_case(ShapeKind shape, UpdateScheme scheme) {
  CaseDescription c = empty_case(Dim, {16, 16, 16}, 0.1);
  c.shape = shape;
  c.scheme = scheme;
  c.materials.push_back(elastic(1000.0, 1e6, 0.3));
  const Vec3d lo = Vec3d::Constant(0.5), hi = Vec3d::Constant(1.1);
  c.bodies.push_back(box_body("block", 0, Dim, lo, hi, 0.1, 2));
  return c;
}

// Random velocities and stresses, so that every term of the transfer is exercised.
template <int Dim>
void randomise(Particles<Dim>& particles, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    for (int d = 0; d < Dim; ++d) particles.velocity[p][d] = u(rng);
    for (auto& s : particles.stress[p]) s = 1e3 * u(rng);
  }
}

template <int Dim>
void expect_transfer_conserves(ShapeKind shape) {
  Solver<Dim> solver(spinning_block_case<Dim>(shape, UpdateScheme::usl));
  randomise(solver.particles(), 7);
  const Totals<Dim> before = solver.totals();
  solver.step(1e-5);
  const Grid<Dim>& grid = solver.grid();
  double mass = 0.0;
  Vec<Dim> momentum = Vec<Dim>::Zero();
  Vec<Dim> force = Vec<Dim>::Zero();
  for (std::size_t i = 0; i < grid.mass.size(); ++i) {
    mass += grid.mass[i];
    momentum += grid.momentum[i];
    force += grid.force[i];
  }
  const double mass_error = std::abs(mass - before.mass) / before.mass;
  const double momentum_error = (momentum - before.momentum).norm() / (before.mass * 1.0);
  std::printf(
      "%dD %s: grid mass error %.2e, momentum error %.2e, net internal force %.2e N (tolerance "
      "1e-12)\n",
      Dim, std::string(to_string(shape)).c_str(), mass_error, momentum_error, force.norm());
  EXPECT_LT(mass_error, 1e-12);
  EXPECT_LT(momentum_error, 1e-12);
  // Internal forces are equilibrated: the gradients of a partition of unity sum to zero.
  EXPECT_LT(force.norm(), 1e-9 * 1e3 * before.mass);
}

TEST(SolverTransfer, ParticleToGridConservesMassAndMomentum2D) {
  for (auto shape : {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline})
    expect_transfer_conserves<2>(shape);
}

TEST(SolverTransfer, ParticleToGridConservesMassAndMomentum3D) {
  for (auto shape : {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline})
    expect_transfer_conserves<3>(shape);
}

TEST(SolverDynamics, FreeFallGainsExactlyGravityTimesTime) {
  for (auto scheme : {UpdateScheme::usl, UpdateScheme::musl}) {
    CaseDescription c = spinning_block_case<2>(ShapeKind::gimp, scheme);
    c.gravity = Vec3d(0.0, -9.81, 0.0);
    Solver<2> solver(c);
    const double dt = 1e-4;
    for (int n = 0; n < 200; ++n) solver.step(dt);
    const Totals<2> t = solver.totals();
    const double expected = -9.81 * 200 * dt;
    for (std::size_t p = 0; p < solver.particles().size(); ++p) {
      ASSERT_NEAR(solver.particles().velocity[p][1], expected, 1e-10);
      ASSERT_NEAR(solver.particles().velocity[p][0], 0.0, 1e-12);
    }
    EXPECT_NEAR(t.momentum[1] / t.mass, expected, 1e-12);
  }
}

template <int Dim>
std::vector<double> run_and_collect(int threads, ShapeKind shape) {
  CaseDescription c = spinning_block_case<Dim>(shape, UpdateScheme::musl);
  c.gravity = Vec3d(0.0, Dim == 2 ? -9.81 : 0.0, Dim == 3 ? -9.81 : 0.0);
  c.boundaries[2 * (Dim - 1)].kind = FaceCondition::Kind::fixed;
  c.bodies[0].positions.front()[Dim - 1] -= 0.45;  // one point near the floor
  c.threads = threads;
  Solver<Dim> solver(c);
  randomise(solver.particles(), 3);
  for (int n = 0; n < 20; ++n) solver.step(0.2 * solver.stable_time_step());
  std::vector<double> state;
  for (std::size_t p = 0; p < solver.particles().size(); ++p) {
    for (int d = 0; d < Dim; ++d) state.push_back(solver.particles().position[p][d]);
    for (int d = 0; d < Dim; ++d) state.push_back(solver.particles().velocity[p][d]);
    for (double s : solver.particles().stress[p]) state.push_back(s);
  }
  return state;
}

TEST(SolverDeterminism, IdenticalBitsForOneAndTwoThreads) {
  const int saved = omp_get_max_threads();
  for (auto shape : {ShapeKind::gimp, ShapeKind::quadratic_bspline}) {
    const auto one = run_and_collect<2>(1, shape);
    const auto two = run_and_collect<2>(2, shape);
    const auto again = run_and_collect<2>(2, shape);
    EXPECT_EQ(one, two);
    EXPECT_EQ(two, again);
    EXPECT_EQ(run_and_collect<3>(1, shape), run_and_collect<3>(2, shape));
  }
  omp_set_num_threads(saved);
}

// 9600 points, above the threshold where the loops go parallel, over 80
// cell rows: the scatter's slabs are fixed by the grid, not by the thread
// count, so the points and the accumulated work have the same bits on one
// thread and on three.
TEST(SolverDeterminism, IdenticalBitsAboveTheParallelThresholdOnOneAndThreeThreads) {
  const int saved = omp_get_max_threads();
  const auto run = [](int threads) {
    CaseDescription c = empty_case(2, {32, 88, 1}, 0.05);
    c.materials.push_back(elastic(1000.0, 1e6, 0.3));
    c.bodies.push_back(
        box_body("block", 0, 2, Vec3d(0.1, 0.1, 0.0), Vec3d(1.6, 4.1, 0.0), 0.05, 2));
    c.threads = threads;
    auto solver = std::make_unique<Solver<2>>(c);
    randomise(solver->particles(), 5);
    for (int n = 0; n < 5; ++n) solver->step(0.2 * solver->stable_time_step());
    return solver;
  };
  const auto one = run(1);
  const auto three = run(3);
  ASSERT_GE(one->particles().size(), 8192u);
  EXPECT_EQ(one->particles().position, three->particles().position);
  EXPECT_EQ(one->particles().stress, three->particles().stress);
  const double w1 = one->totals().internal_work;
  const double w3 = three->totals().internal_work;
  EXPECT_EQ(std::memcmp(&w1, &w3, sizeof(double)), 0) << w1 << " vs " << w3;
  omp_set_num_threads(saved);
}

// Largest spread of the volume change J - 1 among the points of one grid
// cell after one step of a compressing flow whose divergence varies across
// each cell (v_x = -x y; dv_x/dx = -y).
double volume_change_spread_in_cells(LockingMitigation locking) {
  CaseDescription c = spinning_block_case<2>(ShapeKind::gimp, UpdateScheme::usl);
  c.locking = locking;
  Solver<2> solver(c);
  auto& particles = solver.particles();
  std::vector<long> cell(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Vec<2> x = particles.position[p];
    particles.velocity[p] = Vec<2>(-x[0] * x[1], 0.0);
    cell[p] = 1000L * static_cast<long>(std::floor(x[0] / 0.1)) +
              static_cast<long>(std::floor(x[1] / 0.1));
  }
  std::vector<double> initial(particles.volume);
  solver.step(1e-4);
  std::map<long, std::pair<double, double>> range;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double change = particles.volume[p] / initial[p] - 1.0;
    auto [it, inserted] = range.emplace(cell[p], std::make_pair(change, change));
    it->second = {std::min(it->second.first, change), std::max(it->second.second, change)};
  }
  double spread = 0.0;
  for (const auto& [key, r] : range) spread = std::max(spread, r.second - r.first);
  return spread;
}

// B-bar: a point's volume follows the cell-averaged dilatation its stress
// sees, so the points of a cell change volume alike; with their own
// dilatation the volumes drift apart in modes the stress never resists.
TEST(SolverLocking, BbarPointsOfOneCellChangeVolumeAlike) {
  const double none = volume_change_spread_in_cells(LockingMitigation::none);
  const double bbar = volume_change_spread_in_cells(LockingMitigation::bbar);
  const double fbar = volume_change_spread_in_cells(LockingMitigation::fbar);
  std::printf(
      "largest in-cell spread of J - 1: none %.3e, bbar %.3e, fbar %.3e (tolerance 1e-3 x none)\n",
      none, bbar, fbar);
  ASSERT_GT(none, 1e-6);
  EXPECT_LT(bbar, 1e-3 * none);
  EXPECT_LT(fbar, 1e-3 * none);
}

// A point whose state went non-finite between two check_state() calls ends
// the next step with a NumericalError, not an out-of-range index.
TEST(SolverFailure, NonFinitePositionStopsTheNextStepCleanly) {
  Solver<2> solver(spinning_block_case<2>(ShapeKind::gimp, UpdateScheme::usl));
  solver.particles().position[5][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solver.step(1e-4), cosim::NumericalError);
}

// A pre-stressed block spun as a rigid body: the stress must turn with it
// (objectivity of the Jaumann and polar-rotation updates in the solver).
void expect_stress_rotates_with_body(const std::string& rate) {
  CaseDescription c = empty_case(2, {24, 24, 1}, 0.1);
  c.shape = ShapeKind::gimp;
  c.scheme = UpdateScheme::usl;
  c.flip_fraction = 0.0;
  // A soft material: the rotation, not the elastic response to the grid's
  // imperfect rigid-body velocity at the block's edges, must dominate.
  c.materials.push_back(elastic(1000.0, 1.0, 0.3, rate));
  c.bodies.push_back(box_body("block", 0, 2, Vec3d(0.7, 0.7, 0), Vec3d(1.7, 1.7, 0), 0.1, 2));
  Solver<2> solver(c);
  auto& particles = solver.particles();
  const Vec<2> centre(1.2, 1.2);
  const double omega = 1.0;
  const double s0 = 1e4;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Vec<2> r = particles.position[p] - centre;
    particles.velocity[p] = omega * Vec<2>(-r[1], r[0]);
    particles.stress[p] = Voigt{s0, 0, 0, 0, 0, 0};
  }
  // Keep the angular velocity exact: reset velocities to the rigid field each step.
  const double dt = 1e-3;
  const int steps = 300;
  for (int n = 0; n < steps; ++n) {
    solver.step(dt);
    for (std::size_t p = 0; p < particles.size(); ++p) {
      const Vec<2> r = particles.position[p] - centre;
      particles.velocity[p] = omega * Vec<2>(-r[1], r[0]);
    }
  }
  const double angle = omega * dt * steps;
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  Eigen::Matrix2d expected = R * Eigen::Vector2d(s0, 0).asDiagonal() * R.transpose();
  // Points whose grid values are all inside the block: at the edges the grid
  // velocity of a rotating body is a one-sided average, not the rigid field.
  double worst = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if ((particles.position[p] - centre).norm() > 0.25) continue;
    const Tensor s = from_voigt(particles.stress[p]);
    worst = std::max(worst, (s.topLeftCorner<2, 2>() - expected).norm() / s0);
  }
  std::printf(
      "%s: stress after a %.2f rad rigid rotation, worst relative error %.3e (tolerance 5e-3)\n",
      rate.c_str(), angle, worst);
  // The remainder is the transfer error of a rotating point set (the mass-weighted
  // grid velocity is not exactly the rigid field), the same for both rates.
  EXPECT_LT(worst, 5e-3);
}

TEST(SolverObjectivity, JaumannStressTurnsWithRigidRotation) {
  expect_stress_rotates_with_body("jaumann");
}
TEST(SolverObjectivity, PolarRotationStressTurnsWithRigidRotation) {
  expect_stress_rotates_with_body("polar_rotation");
}

// A block deformed by a prescribed affine grid velocity v = L (x - c), with L
// constant: every point sees exactly L (the GIMP weights reproduce linear
// fields inside the grid), so F = (I + dt L)^n. With gimp_domain: deformed the
// half-lengths are l_0,i |F_ii| exactly (the shear term of L leaves them
// alone); with the default they keep their initial value bit for bit.
double worst_domain_error(GimpDomain domain, const Eigen::Matrix2d& L, int steps, double dt) {
  CaseDescription c = empty_case(2, {24, 24, 1}, 0.1);
  c.shape = ShapeKind::gimp;
  c.scheme = UpdateScheme::usl;
  c.flip_fraction = 0.0;
  c.gimp_domain = domain;
  c.materials.push_back(elastic(1000.0, 1.0, 0.3));
  c.bodies.push_back(box_body("block", 0, 2, Vec3d(0.8, 0.8, 0), Vec3d(1.6, 1.6, 0), 0.1, 2));
  Solver<2> solver(c);
  const Vec<2> centre(1.2, 1.2);
  solver.add_grid_velocity_correction([&](double, double, Grid<2>& grid) {
    for (std::size_t i = 0; i < grid.size(); ++i)
      grid.velocity[i] = L * (grid.position(i) - centre);
  });
  const auto& particles = solver.particles();
  const std::vector<Vec<2>> initial = particles.half_length;
  for (int n = 0; n < steps; ++n) solver.step(dt);
  const Eigen::Matrix2d increment = Eigen::Matrix2d::Identity() + dt * L;
  Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
  for (int n = 0; n < steps; ++n) F = increment * F;
  double worst = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    EXPECT_LT((particles.deformation_gradient[p] - F).norm(), 1e-12);
    const Vec<2> expected = domain == GimpDomain::deformed
                                ? Vec<2>(initial[p].cwiseProduct(F.diagonal().cwiseAbs()))
                                : initial[p];
    worst = std::max(
        worst,
        ((particles.half_length[p] - expected).array() / initial[p].array()).abs().maxCoeff());
  }
  return worst;
}

TEST(SolverGimpDomain, DeformedDomainFollowsTheDiagonalOfF) {
  Eigen::Matrix2d L;
  L << 0.5, 0.2, 0.0, -0.3;  // stretch in x, compression in y, shear
  const double worst = worst_domain_error(GimpDomain::deformed, L, 200, 1e-3);
  std::printf("deformed GIMP domain: worst relative half-length error %.2e (tolerance 1e-13)\n",
              worst);
  EXPECT_LT(worst, 1e-13);
}

TEST(SolverGimpDomain, InitialDomainIsUnchangedByDefault) {
  EXPECT_EQ(CaseDescription{}.gimp_domain, GimpDomain::initial);
  Eigen::Matrix2d L;
  L << 0.5, 0.2, 0.0, -0.3;
  EXPECT_EQ(worst_domain_error(GimpDomain::initial, L, 200, 1e-3), 0.0);
}

// Two elastic blocks meeting head-on through frictionless grid contact: the
// contact conserves momentum exactly, creates no energy, and they separate.
TEST(SolverContact, HeadOnCollisionConservesMomentumAndBounces) {
  CaseDescription c = empty_case(2, {40, 12, 1}, 0.05);
  c.shape = ShapeKind::gimp;
  c.contact.enabled = true;
  c.contact.friction = 0.0;
  c.materials.push_back(elastic(1000.0, 1e6, 0.3));
  c.bodies.push_back(box_body("left", 0, 2, Vec3d(0.4, 0.2, 0), Vec3d(0.8, 0.4, 0), 0.05, 2));
  c.bodies.push_back(box_body("right", 0, 2, Vec3d(0.9, 0.2, 0), Vec3d(1.3, 0.4, 0), 0.05, 2));
  c.bodies[0].initial_velocity = Vec3d(1.0, 0, 0);
  c.bodies[1].initial_velocity = Vec3d(-0.5, 0, 0);
  Solver<2> solver(c);
  const Totals<2> start = solver.totals();
  double min_gap = 1e9;
  for (int n = 0; n < 4000 && solver.time() < 0.25; ++n) {
    solver.step(solver.stable_time_step());
    double right_of_left = -1e9, left_of_right = 1e9;
    for (std::size_t p = 0; p < solver.particles().size(); ++p) {
      const double x = solver.particles().position[p][0];
      if (solver.particles().body[p] == 0)
        right_of_left = std::max(right_of_left, x);
      else
        left_of_right = std::min(left_of_right, x);
    }
    min_gap = std::min(min_gap, left_of_right - right_of_left);
  }
  const Totals<2> end = solver.totals();
  const double momentum_error = (end.momentum - start.momentum).norm() / start.mass;
  const double energy_start = start.kinetic_energy + start.strain_energy;
  const double energy_end = end.kinetic_energy + end.strain_energy;
  std::printf(
      "collision: momentum error %.2e m/s (tolerance 1e-12); energy %.3f J -> %.3f J "
      "(kinetic %.3f, strain %.3f; tolerance +8 %%); closest approach of the point centres %.4f "
      "m\n",
      momentum_error, energy_start, energy_end, end.kinetic_energy, end.strain_energy, min_gap);
  EXPECT_LT(momentum_error, 1e-12);
  // Explicit MPM with a FLIP blend is not exactly energy-conserving; a few per cent is usual.
  EXPECT_LT(energy_end, 1.08 * energy_start);
  EXPECT_GT(min_gap, 0.0);  // no interpenetration
  double v_left = 0, v_right = 0, m_left = 0, m_right = 0;
  for (std::size_t p = 0; p < solver.particles().size(); ++p) {
    auto& P = solver.particles();
    (P.body[p] == 0 ? v_left : v_right) += P.mass[p] * P.velocity[p][0];
    (P.body[p] == 0 ? m_left : m_right) += P.mass[p];
  }
  std::printf("collision: mean velocities after %.3f s: left %.4f m/s, right %.4f m/s\n",
              solver.time(), v_left / m_left, v_right / m_right);
  EXPECT_LT(v_left / m_left, v_right / m_right);  // they separate
}

// A block sliding on a fixed rigid floor with Coulomb friction decelerates
// at mu g once it has settled on the floor.
TEST(SolverContact, BlockOnRigidFloorDeceleratesAtMuG) {
  const double h = 0.02, mu = 0.3, v0 = 1.0, g = 9.81;
  CaseDescription c = empty_case(2, {60, 15, 1}, h);
  c.shape = ShapeKind::gimp;
  c.contact.enabled = true;
  c.contact.friction = mu;
  c.gravity = Vec3d(0, -g, 0);
  c.materials.push_back(elastic(2000.0, 5e6, 0.3));
  c.bodies.push_back(box_body("block", 0, 2, Vec3d(0.1, 0.1, 0), Vec3d(0.3, 0.16, 0), h, 2));
  c.bodies[0].geostatic = GeostaticStress{};
  BodySpec floor = box_body("floor", -1, 2, Vec3d(0.0, 0.04, 0), Vec3d(1.2, 0.1, 0), h, 2);
  floor.rigid = RigidMotion{};
  floor.density_override = 2000.0;
  c.bodies.push_back(floor);
  c.bodies[0].initial_velocity = Vec3d(v0, 0, 0);
  Solver<2> solver(c);
  auto mean_velocity = [&] {
    double mv = 0, m = 0;
    for (std::size_t p = 0; p < solver.particles().size(); ++p)
      if (solver.particles().body[p] == 0) {
        mv += solver.particles().mass[p] * solver.particles().velocity[p][0];
        m += solver.particles().mass[p];
      }
    return mv / m;
  };
  while (solver.time() < 0.05) solver.step(solver.stable_time_step());
  const double t1 = solver.time(), v1 = mean_velocity();
  while (solver.time() < 0.25) solver.step(solver.stable_time_step());
  const double t2 = solver.time(), v2 = mean_velocity();
  const double deceleration = (v1 - v2) / (t2 - t1);
  const double error = std::abs(deceleration - mu * g) / (mu * g);
  std::printf(
      "sliding block: deceleration %.4f m/s^2, Coulomb mu g %.4f m/s^2, error %.2f %% (tolerance "
      "10 %%); "
      "friction work %.4f J\n",
      deceleration, mu * g, 100 * error, solver.totals().contact_dissipation);
  EXPECT_LT(error, 0.10);
  EXPECT_GT(solver.totals().contact_dissipation, 0.0);
}

}  // namespace
}  // namespace mpm

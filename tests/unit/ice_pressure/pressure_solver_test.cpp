#include "ice/pressure/pressure_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"
#include "ice/pressure/multigrid_preconditioner.hpp"

namespace {

using ice::PressureBoundary;
using ice::PressurePreconditioner;
constexpr PressureBoundary wall = PressureBoundary::wall;
constexpr PressureBoundary fixed = PressureBoundary::fixed_pressure;

template <int Dim>
ice::CellGrid<Dim> box_grid(const std::array<int, Dim>& cells, double length = 1.0) {
  using Point = typename ice::CellGrid<Dim>::Point;
  Point spacing;
  for (int d = 0; d < Dim; ++d) {
    spacing[d] = length / cells[d];
  }
  return ice::CellGrid<Dim>(Point::Zero(), spacing, cells);
}

template <int Dim>
double divergence(const ice::CellGrid<Dim>& grid, const ice::FaceField<Dim>& u, int cell) {
  double sum = 0.0;
  for (int d = 0; d < Dim; ++d) {
    sum += (u[d][grid.upper_face(d, cell)] - u[d][grid.lower_face(d, cell)]) / grid.spacing()[d];
  }
  return sum;
}

// A problem with physical magnitudes: kappa between water's and air's
// (1e-9 .. 1e-5 1/Pa), face densities 1 .. 1000 kg/m^3, |U*| < 1 m/s.
template <int Dim>
struct RandomProblem {
  std::vector<double> kappa;
  ice::FaceField<Dim> density;
  ice::FaceField<Dim> velocity;
  double dt = 1e-4;
};

template <int Dim>
RandomProblem<Dim> random_problem(const ice::CellGrid<Dim>& grid,
                                  const std::array<PressureBoundary, 2 * Dim>& sides,
                                  unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> log_kappa(-9.0, -5.0);
  std::uniform_real_distribution<double> log_rho(0.0, 3.0);
  std::uniform_real_distribution<double> velocity(-1.0, 1.0);
  RandomProblem<Dim> p;
  p.kappa.resize(static_cast<std::size_t>(grid.cell_count()));
  for (double& k : p.kappa) k = std::pow(10.0, log_kappa(rng));
  p.density = ice::make_face_field(grid);
  p.velocity = ice::make_face_field(grid);
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      p.density[d][f] = std::pow(10.0, log_rho(rng));
      const bool on_wall = (grid.lower_cell(d, f) < 0 && sides[2 * d] == wall) ||
                           (grid.upper_cell(d, f) < 0 && sides[2 * d + 1] == wall);
      p.velocity[d][f] = on_wall ? 0.0 : velocity(rng);
    }
  }
  return p;
}

// sqrt(sum_c (kappa dP / dt + div U)^2) / sqrt(sum_c (div U*)^2): eq. 52
// after the correction, relative to the predicted divergence.
template <int Dim>
double relative_discrete_residual(const ice::CellGrid<Dim>& grid, const RandomProblem<Dim>& p,
                                  const std::vector<double>& dp,
                                  const ice::FaceField<Dim>& corrected, double* max_relative) {
  double residual2 = 0.0;
  double reference2 = 0.0;
  double residual_max = 0.0;
  double reference_max = 0.0;
  for (int c = 0; c < grid.cell_count(); ++c) {
    const double r = p.kappa[c] * dp[c] / p.dt + divergence(grid, corrected, c);
    const double b = divergence(grid, p.velocity, c);
    residual2 += r * r;
    reference2 += b * b;
    residual_max = std::max(residual_max, std::abs(r));
    reference_max = std::max(reference_max, std::abs(b));
  }
  if (max_relative != nullptr) *max_relative = residual_max / reference_max;
  return std::sqrt(residual2 / reference2);
}

template <int Dim>
void expect_discrete_consistency(const std::array<int, Dim>& cells,
                                 const std::array<PressureBoundary, 2 * Dim>& sides,
                                 PressurePreconditioner preconditioner) {
  const auto grid = box_grid<Dim>(cells, 0.3);
  const auto p = random_problem<Dim>(grid, sides, 17u + Dim);
  ice::PressureSolverOptions options;
  options.tolerance = 1e-10;
  options.preconditioner = preconditioner;
  ice::PressureSolver<Dim> solver(grid, sides, options);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  const ice::PressureSolution s = solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
  auto corrected = p.velocity;
  solver.correct_face_velocities(p.density, dp, p.dt, corrected);
  double max_relative = 0.0;
  const double relative = relative_discrete_residual(grid, p, dp, corrected, &max_relative);
  std::printf(
      "  %dD %s: %d iterations, CG relative residual %.2e; "
      "||kappa dP/dt + div U^{n+1}|| / ||div U*|| = %.2e (tol %.0e), max-norm %.2e\n",
      Dim, ice::to_string(preconditioner).c_str(), s.iterations, s.relative_residual, relative,
      2 * options.tolerance, max_relative);
  EXPECT_LE(s.relative_residual, options.tolerance);
  EXPECT_LE(relative, 2 * options.tolerance);
  EXPECT_LE(s.iterations, options.max_iterations);
  // walls keep their given face velocity (0 here)
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const bool on_wall = (grid.lower_cell(d, f) < 0 && sides[2 * d] == wall) ||
                           (grid.upper_cell(d, f) < 0 && sides[2 * d + 1] == wall);
      if (on_wall) {
        EXPECT_EQ(corrected[d][f], p.velocity[d][f]);
      }
    }
  }
}

TEST(PressureSolver, CorrectedVelocitiesSatisfyTheDiscreteVolumeBalance) {
  for (const auto pc : {PressurePreconditioner::jacobi, PressurePreconditioner::incomplete_cholesky,
                        PressurePreconditioner::multigrid}) {
    expect_discrete_consistency<1>({40}, {fixed, wall}, pc);
    expect_discrete_consistency<2>({24, 17}, {fixed, wall, wall, fixed}, pc);
    expect_discrete_consistency<3>({10, 8, 6}, {wall, fixed, wall, wall, fixed, wall}, pc);
  }
}

// A volume source stands for the divergence of the face velocities it
// replaces: the same increment to round-off, and a non-finite or missized
// source is refused.
TEST(PressureSolver, AVolumeSourceActsAsTheDivergenceItStandsFor) {
  const std::array<PressureBoundary, 4> sides{wall, fixed, wall, wall};
  const auto grid = box_grid<2>({12, 9}, 0.3);
  const auto p = random_problem<2>(grid, sides, 5u);
  ice::PressureSolverOptions options;
  options.tolerance = 1e-12;
  ice::PressureSolver<2> solver(grid, sides, options);
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  std::vector<double> from_faces(cells, 0.0), from_source(cells, 0.0), source(cells);
  solver.solve(p.kappa, p.density, p.velocity, p.dt, from_faces);
  // The velocities on open faces stay (they are the boundary's), the
  // interior ones become the source.
  auto boundary_only = p.velocity;
  for (int d = 0; d < 2; ++d)
    for (int f = 0; f < grid.face_count(d); ++f)
      if (grid.lower_cell(d, f) >= 0 && grid.upper_cell(d, f) >= 0) boundary_only[d][f] = 0.0;
  for (int c = 0; c < grid.cell_count(); ++c)
    source[static_cast<std::size_t>(c)] =
        divergence(grid, p.velocity, c) - divergence(grid, boundary_only, c);
  solver.solve(p.kappa, p.density, boundary_only, p.dt, from_source, source);
  double largest = 0.0, worst = 0.0;
  for (std::size_t c = 0; c < cells; ++c) {
    largest = std::max(largest, std::abs(from_faces[c]));
    worst = std::max(worst, std::abs(from_source[c] - from_faces[c]));
  }
  std::printf("  source vs faces: largest |dP| %.3e Pa, worst difference %.2e\n", largest, worst);
  EXPECT_LT(worst, 1e-8 * largest);
  source[3] = std::nan("");
  EXPECT_THROW(solver.solve(p.kappa, p.density, boundary_only, p.dt, from_source, source),
               std::invalid_argument);
  source.pop_back();
  EXPECT_THROW(solver.solve(p.kappa, p.density, boundary_only, p.dt, from_source, source),
               std::invalid_argument);
}

TEST(PressureSolver, MatrixIsSymmetricPositiveDefinite) {
  const auto grid = box_grid<2>({13, 9});
  const std::array<PressureBoundary, 4> sides{fixed, wall, fixed, wall};
  const auto p = random_problem<2>(grid, sides, 3u);
  ice::PressureSolver<2> solver(grid, sides);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  const auto s = solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
  const Eigen::SparseMatrix<double> a = solver.matrix();
  const Eigen::SparseMatrix<double> at = a.transpose();
  const double asymmetry = (a - at).norm();
  std::printf("  ||A - A^T||_F = %.1e (tol 0), ||A||_F = %.2e, %d nonzeros, CG %d iterations\n",
              asymmetry, a.norm(), static_cast<int>(a.nonZeros()), s.iterations);
  EXPECT_EQ(asymmetry, 0.0);
  EXPECT_EQ(a.nonZeros(), grid.cell_count() + 2 * (12 * 9 + 13 * 8));
  // Gershgorin: positive diagonal, weakly diagonally dominant with surplus
  // kappa V / dt (+ the fixed-pressure ghosts).
  double min_surplus = 1e300;
  for (int c = 0; c < grid.cell_count(); ++c) {
    double off = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it) {
      if (it.row() != c) {
        EXPECT_LT(it.value(), 0.0);
        off += std::abs(it.value());
      }
    }
    const double surplus = a.coeff(c, c) - off;
    const double kappa_term = p.kappa[c] * grid.cell_volume() / p.dt;
    EXPECT_GE(surplus, kappa_term * (1 - 1e-12));
    min_surplus = std::min(min_surplus, surplus / kappa_term);
  }
  std::printf("  min (A_cc - sum |A_cn|) / (kappa V / dt) = %.6f (>= 1)\n", min_surplus);
  std::mt19937 rng(5u);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(grid.cell_count());
    for (int c = 0; c < grid.cell_count(); ++c) x[c] = normal(rng);
    EXPECT_GT(x.dot(a * x), 0.0);
  }
}

// The multigrid solve assembles the operator into the preconditioner and
// fills matrix() from it on demand: the same values, to the bit, as the
// sparse assembly of the other preconditioners (1D-3D, walls and fixed
// sides, a matrix asked for before any solve too).
template <int Dim>
void check_multigrid_matrix(const std::array<int, Dim>& cells,
                            const std::array<PressureBoundary, 2 * Dim>& sides, unsigned seed) {
  const auto grid = box_grid<Dim>(cells);
  const auto p = random_problem<Dim>(grid, sides, seed);
  ice::PressureSolverOptions jacobi;
  jacobi.preconditioner = PressurePreconditioner::jacobi;
  jacobi.max_iterations = 20000;
  ice::PressureSolver<Dim> multigrid_solver(grid, sides);
  ice::PressureSolver<Dim> jacobi_solver(grid, sides, jacobi);
  EXPECT_EQ(multigrid_solver.matrix().nonZeros(), jacobi_solver.matrix().nonZeros());
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  multigrid_solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
  std::vector<double> dp_jacobi(dp.size(), 0.0);
  jacobi_solver.solve(p.kappa, p.density, p.velocity, p.dt, dp_jacobi);
  const Eigen::SparseMatrix<double>& a = multigrid_solver.matrix();
  const Eigen::SparseMatrix<double>& b = jacobi_solver.matrix();
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  for (Eigen::Index k = 0; k < a.nonZeros(); ++k) {
    EXPECT_EQ(a.valuePtr()[k], b.valuePtr()[k]) << k;
    EXPECT_EQ(a.innerIndexPtr()[k], b.innerIndexPtr()[k]) << k;
  }
}

TEST(PressureSolver, MultigridMatrixIsTheAssembledOne) {
  check_multigrid_matrix<1>({17}, {fixed, wall}, 51u);
  check_multigrid_matrix<2>({13, 9}, {fixed, wall, fixed, wall}, 52u);
  check_multigrid_matrix<2>({8, 11}, {wall, wall, wall, wall}, 53u);
  check_multigrid_matrix<3>({6, 5, 4}, {fixed, wall, wall, fixed, wall, wall}, 54u);
}

// The pattern is built once and only the values are rewritten: a solver
// that has solved another problem gives bit-for-bit the fresh solver's dP, and
// the solution as initial guess needs no iteration.
TEST(PressureSolver, ReusedSolverMatchesFreshOneAndUsesTheGuess) {
  const auto grid = box_grid<3>({6, 5, 4});
  const std::array<PressureBoundary, 6> sides{fixed, wall, wall, fixed, wall, wall};
  const auto first = random_problem<3>(grid, sides, 41u);
  const auto second = random_problem<3>(grid, sides, 43u);
  ice::PressureSolver<3> reused(grid, sides);
  ice::PressureSolver<3> fresh(grid, sides);
  std::vector<double> dp_first(static_cast<std::size_t>(grid.cell_count()), 0.0);
  reused.solve(first.kappa, first.density, first.velocity, first.dt, dp_first);
  std::vector<double> dp_reused(dp_first.size(), 0.0);
  std::vector<double> dp_fresh(dp_first.size(), 0.0);
  reused.solve(second.kappa, second.density, second.velocity, second.dt, dp_reused);
  fresh.solve(second.kappa, second.density, second.velocity, second.dt, dp_fresh);
  EXPECT_EQ(dp_reused, dp_fresh);
  EXPECT_EQ(reused.matrix().nonZeros(), fresh.matrix().nonZeros());
  std::vector<double> dp_again = dp_fresh;
  const auto s = fresh.solve(second.kappa, second.density, second.velocity, second.dt, dp_again);
  std::printf("  re-solve from the solution: %d iterations (expect 0), relative residual %.2e\n",
              s.iterations, s.relative_residual);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_LE(s.relative_residual, 1e-10);
}

// dP = prod_d sin(pi x_d) on the unit box, dP = 0 on every side, constant
// kappa, rho, dt; U* built so that -div U* is the continuous operator applied
// to dP: U*_d = (c / Dim) (cos(pi x_d) / pi) prod_{e != d} sin(pi x_e) with
// c = kappa / dt + Dim pi^2 dt / rho.
template <int Dim>
double manufactured_error(int n, double* l2_error) {
  std::array<int, Dim> cells;
  cells.fill(n);
  const auto grid = box_grid<Dim>(cells);
  std::array<PressureBoundary, 2 * Dim> sides;
  sides.fill(fixed);
  const double kappa = 0.5;
  const double rho = 2.0;
  const double dt = 0.1;
  const double pi = std::numbers::pi;
  const double c = kappa / dt + Dim * pi * pi * dt / rho;
  auto density = ice::make_face_field(grid, rho);
  auto velocity = ice::make_face_field(grid);
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const auto x = grid.face_centre(d, f);
      double value = c / Dim * std::cos(pi * x[d]) / pi;
      for (int e = 0; e < Dim; ++e) {
        if (e != d) value *= std::sin(pi * x[e]);
      }
      velocity[d][f] = value;
    }
  }
  ice::PressureSolverOptions options;
  options.tolerance = 1e-12;
  ice::PressureSolver<Dim> solver(grid, sides, options);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  const std::vector<double> kappas(dp.size(), kappa);
  solver.solve(kappas, density, velocity, dt, dp);
  double max_error = 0.0;
  double sum2 = 0.0;
  for (int cell = 0; cell < grid.cell_count(); ++cell) {
    const auto x = grid.cell_centre(cell);
    double exact = 1.0;
    for (int d = 0; d < Dim; ++d) exact *= std::sin(pi * x[d]);
    const double e = std::abs(dp[cell] - exact);
    max_error = std::max(max_error, e);
    sum2 += e * e * grid.cell_volume();
  }
  *l2_error = std::sqrt(sum2);
  return max_error;
}

template <int Dim>
void expect_second_order(int n) {
  double l2_coarse = 0.0;
  double l2_fine = 0.0;
  const double max_coarse = manufactured_error<Dim>(n, &l2_coarse);
  const double max_fine = manufactured_error<Dim>(2 * n, &l2_fine);
  const double order_max = std::log2(max_coarse / max_fine);
  const double order_l2 = std::log2(l2_coarse / l2_fine);
  std::printf(
      "  %dD N=%d: Linf %.3e -> %.3e (order %.3f), L2 %.3e -> %.3e (order %.3f), "
      "need > 1.8\n",
      Dim, n, max_coarse, max_fine, order_max, l2_coarse, l2_fine, order_l2);
  EXPECT_GT(order_max, 1.8);
  EXPECT_GT(order_l2, 1.8);
}

TEST(PressureSolver, ManufacturedSolutionConvergesAtSecondOrder) {
  expect_second_order<1>(32);
  expect_second_order<2>(32);
}

TEST(PressureSolver, IncompressibleLimitGivesDivergenceFreeFaceVelocities) {
  const auto grid = box_grid<2>({32, 24});
  const std::array<PressureBoundary, 4> sides{wall, wall, wall, fixed};
  // Incompressible means kappa / dt << dt / (rho dx^2): with rho 1 .. 10,
  // dt 0.1 and dx ~ 0.03 the ratio is ~1e-12 (with the physical dt 1e-4 of
  // random_problem it would only be ~1e-4).
  auto p = random_problem<2>(grid, sides, 11u);
  std::fill(p.kappa.begin(), p.kappa.end(), 1e-12);
  p.dt = 0.1;
  for (auto& rho : p.density) {
    for (double& r : rho) r = 1.0 + std::fmod(r, 9.0);
  }
  ice::PressureSolverOptions options;
  options.tolerance = 1e-10;
  ice::PressureSolver<2> solver(grid, sides, options);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  const auto s = solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
  auto corrected = p.velocity;
  solver.correct_face_velocities(p.density, dp, p.dt, corrected);
  double max_div = 0.0;
  double max_div_star = 0.0;
  for (int c = 0; c < grid.cell_count(); ++c) {
    max_div = std::max(max_div, std::abs(divergence(grid, corrected, c)));
    max_div_star = std::max(max_div_star, std::abs(divergence(grid, p.velocity, c)));
  }
  std::printf("  kappa 1e-12: %d iterations, max |div U^{n+1}| / max |div U*| = %.2e (tol 1e-8)\n",
              s.iterations, max_div / max_div_star);
  EXPECT_LE(max_div / max_div_star, 1e-8);
  // closed on three sides and incompressible: no net flow through the open one
  double open_flux = 0.0;
  double open_flux_scale = 0.0;
  for (int i = 0; i < 32; ++i) {
    open_flux += corrected[1][grid.face(1, {i, 24})];
    open_flux_scale += std::abs(p.velocity[1][grid.face(1, {i, 24})]);
  }
  std::printf("  |net flux through the open side| / sum |U*| there = %.2e (tol 1e-8)\n",
              std::abs(open_flux) / open_flux_scale);
  EXPECT_LE(std::abs(open_flux) / open_flux_scale, 1e-8);
  EXPECT_EQ(corrected[1][grid.face(1, {3, 0})], 0.0);
  EXPECT_EQ(corrected[0][grid.face(0, {32, 5})], 0.0);
}

TEST(PressureSolver, ClosedBoxConvergesAndConservesVolume) {
  const auto grid = box_grid<3>({9, 7, 5});
  std::array<PressureBoundary, 6> sides;
  sides.fill(wall);
  const auto p = random_problem<3>(grid, sides, 23u);
  ice::PressureSolver<3> solver(grid, sides);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  const auto s = solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
  auto corrected = p.velocity;
  solver.correct_face_velocities(p.density, dp, p.dt, corrected);
  double max_relative = 0.0;
  const double relative = relative_discrete_residual(grid, p, dp, corrected, &max_relative);
  // walls carry no flux, so sum_c kappa dP V / dt = -sum_c div U* V = 0
  double total = 0.0;
  double scale = 0.0;
  for (int c = 0; c < grid.cell_count(); ++c) {
    total += p.kappa[c] * dp[c];
    scale += std::abs(p.kappa[c] * dp[c]);
  }
  std::printf(
      "  closed 3D box: %d iterations, residual %.2e (tol 2e-10); "
      "|sum kappa dP| / sum |kappa dP| = %.2e (tol 1e-9)\n",
      s.iterations, relative, std::abs(total) / scale);
  EXPECT_LE(relative, 2e-10);
  EXPECT_LE(std::abs(total) / scale, 1e-9);
}

TEST(PressureSolver, NonConvergenceThrowsNumericalErrorWithIterationCount) {
  const auto grid = box_grid<2>({20, 20});
  const std::array<PressureBoundary, 4> sides{fixed, wall, wall, wall};
  const auto p = random_problem<2>(grid, sides, 29u);
  ice::PressureSolverOptions options;
  options.max_iterations = 1;
  options.preconditioner = PressurePreconditioner::jacobi;
  ice::PressureSolver<2> solver(grid, sides, options);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  try {
    solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
    FAIL() << "expected cosim::NumericalError";
  } catch (const cosim::NumericalError& e) {
    const std::string message = e.what();
    std::printf("  message: %s\n", message.c_str());
    EXPECT_NE(message.find("in 1 iterations"), std::string::npos);
    EXPECT_NE(message.find("relative residual"), std::string::npos);
  }
  EXPECT_TRUE(std::all_of(dp.begin(), dp.end(), [](double v) { return v == 0.0; }));
}

TEST(PressureSolver, RejectsBadInput) {
  const auto grid = box_grid<2>({4, 3});
  const std::array<PressureBoundary, 4> sides{fixed, wall, wall, wall};
  const auto p = random_problem<2>(grid, sides, 31u);
  ice::PressureSolver<2> solver(grid, sides);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  std::vector<double> short_dp(3, 0.0);
  std::vector<double> short_kappa(5, 1.0);
  EXPECT_THROW(solver.solve(short_kappa, p.density, p.velocity, p.dt, dp), std::invalid_argument);
  EXPECT_THROW(solver.solve(p.kappa, p.density, p.velocity, p.dt, short_dp), std::invalid_argument);
  auto short_faces = p.density;
  short_faces[1].pop_back();
  EXPECT_THROW(solver.solve(p.kappa, short_faces, p.velocity, p.dt, dp), std::invalid_argument);
  EXPECT_THROW(solver.solve(p.kappa, p.density, short_faces, p.dt, dp), std::invalid_argument);
  for (const double bad : {0.0, -1.0, std::nan("")}) {
    auto kappa = p.kappa;
    kappa[5] = bad;
    EXPECT_THROW(solver.solve(kappa, p.density, p.velocity, p.dt, dp), std::invalid_argument);
    auto density = p.density;
    density[0][6] = bad;  // an interior face
    EXPECT_THROW(solver.solve(p.kappa, density, p.velocity, p.dt, dp), std::invalid_argument);
    EXPECT_THROW(solver.correct_face_velocities(density, dp, p.dt, short_faces = p.velocity),
                 std::invalid_argument);
    EXPECT_THROW(solver.solve(p.kappa, p.density, p.velocity, bad, dp), std::invalid_argument);
    EXPECT_THROW(solver.correct_face_velocities(p.density, dp, bad, short_faces = p.velocity),
                 std::invalid_argument);
  }
  auto velocity = p.velocity;
  velocity[1][2] = std::nan("");
  EXPECT_THROW(solver.solve(p.kappa, p.density, velocity, p.dt, dp), std::invalid_argument);
  auto face_velocity = p.velocity;
  EXPECT_THROW(solver.correct_face_velocities(p.density, short_dp, p.dt, face_velocity),
               std::invalid_argument);
  face_velocity[0].pop_back();
  EXPECT_THROW(solver.correct_face_velocities(p.density, dp, p.dt, face_velocity),
               std::invalid_argument);
  ice::PressureSolverOptions options;
  options.tolerance = 0.0;
  EXPECT_THROW(ice::PressureSolver<2>(grid, sides, options), std::invalid_argument);
  options = {};
  options.max_iterations = 0;
  EXPECT_THROW(ice::PressureSolver<2>(grid, sides, options), std::invalid_argument);
  EXPECT_THROW(ice::pressure_boundary_from_name("outflow"), std::invalid_argument);
  EXPECT_EQ(ice::pressure_boundary_from_name("fixed_pressure"), fixed);
  EXPECT_EQ(ice::to_string(wall), "wall");
  std::vector<double> pressure(3, 1.0);
  EXPECT_THROW(ice::add_pressure_increment(pressure, short_kappa), std::invalid_argument);
  const std::vector<double> increment{0.5, -1.0, 2.0};
  ice::add_pressure_increment(pressure, increment);
  EXPECT_EQ(pressure, (std::vector<double>{1.5, 0.0, 3.0}));
}

// Every preconditioner converges on a larger grid (2D 64 x 64) for the
// random physical problem and a uniform one (air: rho 1.2, kappa 1 / (rho
// c^2) = 7.2e-6); iteration counts are printed. Their timing belongs in a
// benchmark (tests/bench/ice_bench.cpp).
TEST(PressureSolver, EveryPreconditionerConvergesOnALargerGrid) {
  const int n = 64;
  const auto grid = box_grid<2>({n, n});
  const std::array<PressureBoundary, 4> sides{wall, wall, wall, fixed};
  auto random = random_problem<2>(grid, sides, 37u);
  auto uniform = random;
  std::fill(uniform.kappa.begin(), uniform.kappa.end(), 7.2e-6);
  for (auto& rho : uniform.density) std::fill(rho.begin(), rho.end(), 1.2);
  for (const auto* p : {&random, &uniform}) {
    for (const auto pc :
         {PressurePreconditioner::jacobi, PressurePreconditioner::incomplete_cholesky,
          PressurePreconditioner::multigrid}) {
      ice::PressureSolverOptions options;
      options.tolerance = 1e-10;
      options.max_iterations = 20000;
      options.preconditioner = pc;
      ice::PressureSolver<2> solver(grid, sides, options);
      std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
      const ice::PressureSolution s = solver.solve(p->kappa, p->density, p->velocity, p->dt, dp);
      std::printf("  2D %dx%d %s problem, %s: %d iterations, relative residual %.2e (tol 1e-10)\n",
                  n, n, p == &random ? "random" : "uniform", ice::to_string(pc).c_str(),
                  s.iterations, s.relative_residual);
      EXPECT_LE(s.relative_residual, 1e-10);
    }
  }
}

}  // namespace

namespace {

// Water under air in 2D/3D (Dim 1: along the column): face density 1000
// below `interface_fraction` of the height, 1 above; kappa 5e-10 (water)
// and 7e-6 (air) 1/Pa; dt 1e-4 s, dx 1e-3 m; U* random in [-1, 1] m/s.
template <int Dim>
RandomProblem<Dim> water_under_air(const ice::CellGrid<Dim>& grid,
                                   const std::array<PressureBoundary, 2 * Dim>& sides,
                                   double interface_fraction, unsigned seed) {
  RandomProblem<Dim> p = random_problem<Dim>(grid, sides, seed);
  const int up = Dim - 1;
  const double height = grid.upper()[up] - grid.origin()[up];
  const double level = grid.origin()[up] + interface_fraction * height;
  for (int c = 0; c < grid.cell_count(); ++c) {
    p.kappa[static_cast<std::size_t>(c)] = grid.cell_centre(c)[up] < level ? 5e-10 : 7e-6;
  }
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      p.density[d][f] = grid.face_centre(d, f)[up] < level ? 1000.0 : 1.0;
    }
  }
  p.dt = 1e-4;
  return p;
}

template <int Dim>
RandomProblem<Dim> uniform_air(const ice::CellGrid<Dim>& grid,
                               const std::array<PressureBoundary, 2 * Dim>& sides, unsigned seed) {
  RandomProblem<Dim> p = random_problem<Dim>(grid, sides, seed);
  std::fill(p.kappa.begin(), p.kappa.end(), 7.2e-6);
  for (auto& rho : p.density) std::fill(rho.begin(), rho.end(), 1.2);
  return p;
}

template <int Dim>
ice::PressureSolution solve_with(const ice::CellGrid<Dim>& grid,
                                 const std::array<PressureBoundary, 2 * Dim>& sides,
                                 const RandomProblem<Dim>& p, ice::PressureSolverOptions options,
                                 std::vector<double>& dp) {
  ice::PressureSolver<Dim> solver(grid, sides, options);
  dp.assign(static_cast<std::size_t>(grid.cell_count()), 0.0);
  return solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
}

// The multigrid-preconditioned dP is Jacobi's: both solved to 1e-13 on
// random and water-air problems, odd cell counts, walls and fixed_pressure
// sides, 1D to 3D.
template <int Dim>
void expect_multigrid_matches_jacobi(const std::array<int, Dim>& cells,
                                     const std::array<PressureBoundary, 2 * Dim>& sides) {
  const auto grid = box_grid<Dim>(cells, cells[0] * 1e-3);
  for (const bool water_air : {false, true}) {
    const auto p = water_air ? water_under_air<Dim>(grid, sides, 0.45, 7u)
                             : random_problem<Dim>(grid, sides, 13u);
    ice::PressureSolverOptions options;
    options.tolerance = 1e-13;
    options.max_iterations = 100000;
    options.preconditioner = PressurePreconditioner::jacobi;
    std::vector<double> dp_jacobi;
    const auto jacobi = solve_with<Dim>(grid, sides, p, options, dp_jacobi);
    options.preconditioner = PressurePreconditioner::multigrid;
    std::vector<double> dp_multigrid;
    const auto multigrid = solve_with<Dim>(grid, sides, p, options, dp_multigrid);
    double difference = 0.0;
    double size = 0.0;
    for (std::size_t c = 0; c < dp_jacobi.size(); ++c) {
      difference = std::max(difference, std::abs(dp_multigrid[c] - dp_jacobi[c]));
      size = std::max(size, std::abs(dp_jacobi[c]));
    }
    std::printf(
        "  %dD %d cells %s: jacobi %d, multigrid %d iterations; max |dP_mg - dP_jacobi| / max "
        "|dP| = %.2e (tol 1e-9)\n",
        Dim, grid.cell_count(), water_air ? "water-air" : "random", jacobi.iterations,
        multigrid.iterations, difference / size);
    EXPECT_LE(difference / size, 1e-9);
    EXPECT_LE(multigrid.relative_residual, options.tolerance);
  }
}

TEST(PressureSolverMultigrid, GivesJacobisPressureIncrement) {
  expect_multigrid_matches_jacobi<1>({301}, {fixed, wall});
  expect_multigrid_matches_jacobi<1>({97}, {wall, wall});
  expect_multigrid_matches_jacobi<2>({37, 29}, {fixed, wall, wall, fixed});
  expect_multigrid_matches_jacobi<2>({64, 45}, {wall, wall, wall, wall});
  expect_multigrid_matches_jacobi<3>({11, 9, 7}, {wall, fixed, wall, wall, wall, fixed});
  expect_multigrid_matches_jacobi<3>({16, 13, 12}, {wall, wall, wall, wall, wall, wall});
}

// Iteration counts (deterministic) to the default tolerance 1e-10 on the
// grids and problems the ICE step meets: they stay near 8 from 1e3 to 1e6
// cells and across the 1000:1 density jump.
template <int Dim>
int multigrid_iterations(const std::array<int, Dim>& cells,
                         const std::array<PressureBoundary, 2 * Dim>& sides, bool water_air,
                         int jacobi_comparison = 0, double y_spacing = 1e-3) {
  using Point = typename ice::CellGrid<Dim>::Point;
  Point spacing = Point::Constant(1e-3);
  if (Dim > 1) spacing[1] = y_spacing;
  const ice::CellGrid<Dim> grid(Point::Zero(), spacing, cells);
  const auto p =
      water_air ? water_under_air<Dim>(grid, sides, 0.4, 5u) : uniform_air<Dim>(grid, sides, 3u);
  ice::PressureSolverOptions options;
  std::vector<double> dp;
  const auto s = solve_with<Dim>(grid, sides, p, options, dp);
  std::string jacobi;
  if (jacobi_comparison != 0) {
    options.preconditioner = PressurePreconditioner::jacobi;
    options.max_iterations = 100000;
    jacobi = ", jacobi " + std::to_string(solve_with<Dim>(grid, sides, p, options, dp).iterations);
  }
  std::string shape = std::to_string(cells[0]);
  for (int d = 1; d < Dim; ++d) shape += "x" + std::to_string(cells[d]);
  std::printf(
      "  %dD %s dx %.0e dy %.0e %s, %s: multigrid %d iterations%s, relative residual %.2e\n", Dim,
      shape.c_str(), grid.spacing()[0], grid.spacing()[Dim - 1 > 0 ? 1 : 0],
      water_air ? "water under air" : "uniform air",
      sides[2 * Dim - 1] == fixed ? "open top" : "closed", s.iterations, jacobi.c_str(),
      s.relative_residual);
  EXPECT_LE(s.relative_residual, options.tolerance);
  return s.iterations;
}

TEST(PressureSolverMultigrid, IterationCountsOnUniformAndWaterAirProblems) {
  const std::array<PressureBoundary, 4> open{wall, wall, wall, fixed};
  const std::array<PressureBoundary, 4> closed{wall, wall, wall, wall};
  EXPECT_LT(multigrid_iterations<2>({256, 256}, open, false, 1), 15);
  EXPECT_LT(multigrid_iterations<2>({256, 256}, open, true, 1), 15);
  EXPECT_LT(multigrid_iterations<2>({256, 256}, closed, false), 15);
  EXPECT_LT(multigrid_iterations<2>({256, 256}, closed, true), 15);
  EXPECT_LT(multigrid_iterations<2>({255, 257}, closed, true), 15);
  EXPECT_LT(multigrid_iterations<2>({1000, 1000}, closed, true), 15);
  EXPECT_LT(multigrid_iterations<1>({1000}, {wall, fixed}, true), 15);
  EXPECT_LT(multigrid_iterations<1>({999}, {wall, wall}, true), 15);
  EXPECT_LT(multigrid_iterations<3>({64, 64, 64}, {wall, wall, wall, wall, wall, fixed}, true), 15);
  EXPECT_LT(multigrid_iterations<3>({33, 17, 45}, {wall, wall, wall, wall, wall, wall}, false), 15);
  // stretched cells: semi-coarsening along the short side first
  EXPECT_LT(multigrid_iterations<2>({256, 256}, closed, true, 0, 4e-3), 15);
  EXPECT_LT(multigrid_iterations<2>({256, 64}, open, true, 0, 0.25e-3), 15);
}

TEST(PressureSolverMultigrid, NonConvergenceThrowsNumericalError) {
  const auto grid = box_grid<2>({40, 40});
  const std::array<PressureBoundary, 4> sides{fixed, wall, wall, wall};
  const auto p = random_problem<2>(grid, sides, 29u);
  ice::PressureSolverOptions options;
  options.max_iterations = 1;
  ice::PressureSolver<2> solver(grid, sides, options);
  std::vector<double> dp(static_cast<std::size_t>(grid.cell_count()), 0.0);
  try {
    solver.solve(p.kappa, p.density, p.velocity, p.dt, dp);
    FAIL() << "expected cosim::NumericalError";
  } catch (const cosim::NumericalError& e) {
    const std::string message = e.what();
    std::printf("  message: %s\n", message.c_str());
    EXPECT_NE(message.find("in 1 iterations"), std::string::npos);
  }
  EXPECT_TRUE(std::all_of(dp.begin(), dp.end(), [](double v) { return v == 0.0; }));
  std::vector<double> zero_velocity_dp(dp.size(), 3.0);
  const auto still = ice::make_face_field(grid);
  const auto s = solver.solve(p.kappa, p.density, still, p.dt, zero_velocity_dp);
  EXPECT_EQ(s.iterations, 0);
  EXPECT_TRUE(std::all_of(zero_velocity_dp.begin(), zero_velocity_dp.end(),
                          [](double v) { return v == 0.0; }));
}

TEST(PressureSolverMultigrid, PreconditionerNames) {
  for (const auto pc : {PressurePreconditioner::jacobi, PressurePreconditioner::incomplete_cholesky,
                        PressurePreconditioner::multigrid}) {
    EXPECT_EQ(ice::pressure_preconditioner_from_name(ice::to_string(pc)), pc);
  }
  EXPECT_EQ(ice::to_string(PressurePreconditioner::multigrid), "multigrid");
  EXPECT_EQ(ice::PressureSolverOptions{}.preconditioner, PressurePreconditioner::multigrid);
  EXPECT_THROW(ice::pressure_preconditioner_from_name("amg"), std::invalid_argument);
}

// A random operator of the pressure form: positive couplings, row surplus
// between 1e-6 and 1 times them.
template <int Dim>
void set_random_operator(ice::MultigridPreconditioner<Dim>& mg, const std::array<int, Dim>& cells,
                         unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> log_value(-3.0, 0.0);
  std::uniform_real_distribution<double> log_surplus(-6.0, 0.0);
  int stride = 1;
  std::array<int, Dim> strides;
  for (int d = 0; d < Dim; ++d) {
    strides[d] = stride;
    stride *= cells[d];
  }
  std::vector<double> diagonal(static_cast<std::size_t>(mg.cell_count()));
  for (int c = 0; c < mg.cell_count(); ++c) diagonal[c] = std::pow(10.0, log_surplus(rng));
  for (int d = 0; d < Dim; ++d) {
    for (int c = 0; c < mg.cell_count(); ++c) {
      const bool last = (c / strides[d]) % cells[d] == cells[d] - 1;
      const double t = last ? 0.0 : std::pow(10.0, log_value(rng));
      mg.coupling(d, c) = t;
      diagonal[c] += t;
      if (!last) diagonal[c + strides[d]] += t;
    }
  }
  for (int c = 0; c < mg.cell_count(); ++c) mg.diagonal(c) = diagonal[c];
  mg.update();
}

// Coarsening by 2 per direction down to at most 64 cells; odd counts end in
// one-cell aggregates; cells 4 times taller than wide are first coarsened
// along x only. With coupling_scale 1 each coarse operator is P^T A P for
// the piecewise-constant P of the aggregates.
TEST(MultigridPreconditioner, HierarchyIsTheGalerkinOneOfTheAggregates) {
  ice::MultigridPreconditioner<2> big({316, 316}, {1.0, 1.0});
  std::string levels;
  for (int l = 0; l < big.level_count(); ++l) levels += " " + std::to_string(big.level_cells(l)[0]);
  std::printf("  316 x 316 levels:%s\n", levels.c_str());
  EXPECT_EQ(big.level_count(), 7);
  EXPECT_EQ(big.level_cells(6)[0], 5);
  ice::MultigridPreconditioner<1> line({1000}, {1.0});
  EXPECT_EQ(line.level_cells(line.level_count() - 1)[0], 63);
  EXPECT_EQ(ice::MultigridPreconditioner<3>({10, 8, 6}, {1.0, 1.0, 1.0}).level_count(), 2);
  EXPECT_EQ(ice::MultigridPreconditioner<3>({1, 1, 1}, {1.0, 1.0, 1.0}).level_count(), 1);
  ice::MultigridPreconditioner<2> tall({64, 64}, {1.0, 4.0});
  EXPECT_EQ(tall.level_cells(1), (std::array<int, 2>{32, 64}));
  EXPECT_EQ(tall.level_cells(2), (std::array<int, 2>{16, 64}));
  EXPECT_EQ(tall.level_cells(3), (std::array<int, 2>{8, 32}));

  const std::array<int, 3> cells{9, 6, 5};
  ice::MultigridOptions options;
  options.coupling_scale = 1.0;
  options.coarsest_cells = 12;
  ice::MultigridPreconditioner<3> mg(cells, {1.0, 1.1, 0.9}, options);
  set_random_operator<3>(mg, cells, 19u);
  ASSERT_EQ(mg.level_count(), 3);  // 9x6x5 -> 5x3x3 -> 3x2x2
  double worst = 0.0;
  for (int l = 0; l + 1 < mg.level_count(); ++l) {
    const auto fine = mg.level_cells(l);
    const auto coarse = mg.level_cells(l + 1);
    const Eigen::SparseMatrix<double> a = mg.level_operator(l);
    std::vector<Eigen::Triplet<double>> p_entries;
    for (int k = 0; k < fine[2]; ++k) {
      for (int j = 0; j < fine[1]; ++j) {
        for (int i = 0; i < fine[0]; ++i) {
          p_entries.emplace_back(i + fine[0] * (j + fine[1] * k),
                                 i / 2 + coarse[0] * (j / 2 + coarse[1] * (k / 2)), 1.0);
        }
      }
    }
    Eigen::SparseMatrix<double> p(a.rows(), coarse[0] * coarse[1] * coarse[2]);
    p.setFromTriplets(p_entries.begin(), p_entries.end());
    const Eigen::SparseMatrix<double> galerkin = Eigen::SparseMatrix<double>(p.transpose()) * a * p;
    const Eigen::SparseMatrix<double> difference = galerkin - mg.level_operator(l + 1);
    worst = std::max(worst, difference.norm() / galerkin.norm());
  }
  std::printf("  ||P^T A P - A_coarse||_F / ||P^T A P||_F = %.2e (tol 1e-14)\n", worst);
  EXPECT_LE(worst, 1e-14);
}

// CG needs a symmetric positive definite preconditioner: <r2, M r1> =
// <r1, M r2> and <r, M r> > 0; with one level M is A^{-1}.
TEST(MultigridPreconditioner, IsSymmetricPositiveDefinite) {
  const std::array<int, 2> cells{37, 23};
  ice::MultigridPreconditioner<2> mg(cells, {1.0, 1.0});
  set_random_operator<2>(mg, cells, 23u);
  EXPECT_GE(mg.level_count(), 3);
  std::mt19937 rng(7u);
  std::normal_distribution<double> normal;
  const Eigen::Index n = mg.cell_count();
  const Eigen::Index pad = mg.padding();
  double worst_asymmetry = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::VectorXd r1 = Eigen::VectorXd::Zero(mg.padded_size());
    Eigen::VectorXd r2 = r1;
    Eigen::VectorXd z1 = r1;
    Eigen::VectorXd z2 = r1;
    for (Eigen::Index c = 0; c < n; ++c) {
      r1[pad + c] = normal(rng);
      r2[pad + c] = normal(rng);
    }
    mg.apply(r1, z1);
    mg.apply(r2, z2);
    const double a = r2.dot(z1);
    const double b = r1.dot(z2);
    worst_asymmetry = std::max(worst_asymmetry, std::abs(a - b) / std::abs(a));
    EXPECT_GT(r1.dot(z1), 0.0);
  }
  std::printf("  max |<r2, M r1> - <r1, M r2>| / |<r2, M r1>| = %.2e (tol 1e-10)\n",
              worst_asymmetry);
  EXPECT_LE(worst_asymmetry, 1e-10);

  ice::MultigridOptions one_level;
  one_level.coarsest_cells = 1000;
  ice::MultigridPreconditioner<2> exact(cells, {1.0, 1.0}, one_level);
  set_random_operator<2>(exact, cells, 23u);
  ASSERT_EQ(exact.level_count(), 1);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(exact.padded_size());
  for (Eigen::Index c = 0; c < n; ++c) r[pad + c] = normal(rng);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(exact.padded_size());
  Eigen::VectorXd az = z;
  exact.apply(r, z);
  exact.multiply(z, az);
  const double error = (az - r).norm() / r.norm();
  std::printf("  one level: ||A M r - r|| / ||r|| = %.2e (tol 1e-10)\n", error);
  EXPECT_LE(error, 1e-10);
}

TEST(MultigridPreconditioner, RejectsBadOptions) {
  ice::MultigridOptions options;
  options.smoothing_sweeps = 0;
  EXPECT_THROW(ice::MultigridPreconditioner<2>({8, 8}, {1.0, 1.0}, options), std::invalid_argument);
  options = {};
  options.cycle = 3;
  EXPECT_THROW(ice::MultigridPreconditioner<2>({8, 8}, {1.0, 1.0}, options), std::invalid_argument);
  options = {};
  options.coupling_scale = 0.0;
  EXPECT_THROW(ice::MultigridPreconditioner<2>({8, 8}, {1.0, 1.0}, options), std::invalid_argument);
  EXPECT_THROW(ice::MultigridPreconditioner<2>({8, 0}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(ice::MultigridPreconditioner<2>({8, 8}, {1.0, 0.0}), std::invalid_argument);
}

}  // namespace

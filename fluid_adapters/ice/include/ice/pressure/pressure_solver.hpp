#pragma once

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"
#include "ice/pressure/multigrid_preconditioner.hpp"
#include "ice/pressure/pressure_system_solver.hpp"

namespace ice {

// What a domain side does to the pressure increment and the face velocities.
//   wall:           no flux through the side: the dP gradient does not enter
//                   and the given face velocity (normally 0) is kept.
//   fixed_pressure: dP = 0 on the side (a ghost half a cell out); the face
//                   velocity is corrected with the one-sided gradient.
enum class PressureBoundary { wall, fixed_pressure };

// "wall" or "fixed_pressure"; throws std::invalid_argument otherwise.
PressureBoundary pressure_boundary_from_name(const std::string& name);
std::string to_string(PressureBoundary boundary);

// Preconditioner of the conjugate gradients. Measured on 2D 256x256, walls
// and one fixed_pressure side, tolerance 1e-10 (one core): Jacobi 315
// iterations / 92 ms per solve (random kappa and rho over 3-4 decades) and
// 235 / 72 ms (uniform air); Eigen's incomplete Cholesky (thresholded, AMD
// ordering) 218 / 282 ms and 106 / 154 ms: fewer iterations, but its
// factorisation and triangular solves cost more than they save. Multigrid
// (MultigridPreconditioner, one V-cycle per iteration, the default) needs
// 7-12 iterations from 1e3 to 1e6 cells, uniform or water under air (1000:1
// density jump); in the 2D water-column step (tests/bench/ice_bench.cpp,
// 316^2) 7.7 iterations per step against Jacobi's 1502, the whole step
// 1.39M against 0.144M cell-updates/s. Random coefficients over 3 decades
// per face (no geometric structure) still take 30-70.
enum class PressurePreconditioner { jacobi, incomplete_cholesky, multigrid };

// "jacobi", "incomplete_cholesky" or "multigrid"; throws
// std::invalid_argument otherwise.
PressurePreconditioner pressure_preconditioner_from_name(const std::string& name);
std::string to_string(PressurePreconditioner preconditioner);

struct PressureSolverOptions {
  // Relative residual ||b - A dP|| / ||b|| to reach.
  double tolerance = 1e-10;
  int max_iterations = 2000;
  PressurePreconditioner preconditioner = PressurePreconditioner::multigrid;
  // Used with PressurePreconditioner::multigrid only.
  MultigridOptions multigrid;
};

// The implicit pressure increment of the ICE step, Tran et al., MPMICE,
// eq. 125 (derived in eqs. 120-125; eq. 52 for several materials), written
// dimensionally consistent (the printed eq. 125 drops a 1/dt on kappa):
//
//   (kappa / dt) dP - div( (dt / rho_FC) grad^FC dP ) = - div U*_FC,
//
// per cell c with the face sums div_c U = sum_faces +-U_f A_f / V and
// grad^FC dP = (dP_upper - dP_lower) / dx. Multiplied through by V the matrix
//
//   A_cc = kappa_c V / dt + sum_faces (dt / rho_f) A_f / dx_f  (x2 at a
//          fixed_pressure side, none at a wall),
//   A_cn = -(dt / rho_f) A_f / dx_f  for the neighbour n across face f,
//
// is symmetric positive definite for kappa > 0; it is solved by
// preconditioned conjugate gradients. The sparsity is built once; each solve
// rewrites only the values.
//
// Several materials (eq. 52): pass U*_FC = sum_f phi_f,FC U*_f,FC and
// 1 / rho_FC = sum_f phi_f,FC / rho_f,FC; then correct each material's face
// velocities with its own rho_f,FC through correct_face_velocities.
//
// Sides are indexed 2 d (lower) and 2 d + 1 (upper) for direction d.
template <int Dim>
class PressureSolver final : public PressureSystemSolver<Dim> {
 public:
  using Boundaries = std::array<PressureBoundary, 2 * Dim>;

  // Throws std::invalid_argument for a non-positive or non-finite tolerance
  // or max_iterations below one.
  PressureSolver(const CellGrid<Dim>& grid, const Boundaries& boundaries,
                 PressureSolverOptions options = {});

  const CellGrid<Dim>& grid() const { return grid_; }
  const Boundaries& boundaries() const { return boundaries_; }
  const PressureSolverOptions& options() const { return options_; }

  // Solves eq. 125 for dP. `kappa` is the mixture compressibility per cell
  // (> 0), `face_density` rho_FC per face (> 0 on every face that enters:
  // interior and fixed_pressure faces), `predicted_velocity` U*_FC. On entry
  // `pressure_increment` is the initial guess, on exit dP. `volume_source`
  // (one value per cell, or empty for none) is a rate [1/s] at which pore
  // space opens in a cell besides the face fluxes: it adds to div U*_FC.
  // Throws std::invalid_argument for wrong sizes, non-positive or non-finite
  // kappa, dt or density and non-finite velocities; cosim::NumericalError
  // when CG does not reach the tolerance within max_iterations.
  PressureSolution solve(std::span<const double> kappa, const FaceField<Dim>& face_density,
                         const FaceField<Dim>& predicted_velocity, double dt,
                         std::span<double> pressure_increment,
                         std::span<const double> volume_source) override;
  PressureSolution solve(std::span<const double> kappa, const FaceField<Dim>& face_density,
                         const FaceField<Dim>& predicted_velocity, double dt,
                         std::span<double> pressure_increment) {
    return solve(kappa, face_density, predicted_velocity, dt, pressure_increment, {});
  }

  // U^{n+1}_FC = U*_FC - (dt / rho_FC) grad^FC dP on interior faces and
  // fixed_pressure sides (half-cell gradient to dP = 0); walls unchanged.
  // `face_velocity` holds U* on entry and U^{n+1} on exit. Throws
  // std::invalid_argument as solve does.
  void correct_face_velocities(const FaceField<Dim>& face_density,
                               std::span<const double> pressure_increment, double dt,
                               FaceField<Dim>& face_velocity) const;

  // V times the operator of eq. 125, as assembled by the last solve.
  const Eigen::SparseMatrix<double>& matrix() const;

 private:
  void assemble(std::span<const double> kappa, const FaceField<Dim>& face_density, double dt);
  void set_right_hand_side(const FaceField<Dim>& predicted_velocity,
                           std::span<const double> volume_source);
  template <class Solver>
  PressureSolution run(Solver& solver, std::span<double> pressure_increment);
  PressureSolution run_multigrid(std::span<double> pressure_increment);
  void throw_not_converged(const PressureSolution& result) const;
  void require_entering_densities(const FaceField<Dim>& face_density) const;

  CellGrid<Dim> grid_;
  Boundaries boundaries_;
  PressureSolverOptions options_;
  // With the multigrid the operator is assembled into the preconditioner
  // and copied into matrix_ only when matrix() is called.
  mutable Eigen::SparseMatrix<double> matrix_;
  mutable bool matrix_current_ = true;
  // Per direction and face: its lower and upper cell (-1 outside).
  std::array<std::vector<std::array<int, 2>>, static_cast<std::size_t>(Dim)> face_cells_;
  // Positions in matrix_.valuePtr(): per cell its diagonal; per interior
  // face the (lower, upper) and (upper, lower) entries, -1 on the boundary.
  std::vector<std::ptrdiff_t> diagonal_entry_;
  std::array<std::vector<std::ptrdiff_t>, static_cast<std::size_t>(Dim)> lower_upper_entry_;
  std::array<std::vector<std::ptrdiff_t>, static_cast<std::size_t>(Dim)> upper_lower_entry_;
  Eigen::VectorXd right_hand_side_;
  Eigen::VectorXd solution_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      jacobi_cg_;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double>>
      cholesky_cg_;
  // Multigrid-preconditioned CG: the preconditioner and the CG vectors in
  // its padded layout (right-hand side, solution, residual, preconditioned
  // residual, search direction, operator times search direction).
  std::unique_ptr<MultigridPreconditioner<Dim>> multigrid_;
  Eigen::VectorXd padded_rhs_;
  Eigen::VectorXd padded_solution_;
  Eigen::VectorXd padded_residual_;
  Eigen::VectorXd padded_preconditioned_;
  Eigen::VectorXd padded_direction_;
  Eigen::VectorXd padded_product_;
};

// P^{n+1} = P^n + dP, Tran et al., MPMICE, eq. 53. Throws
// std::invalid_argument for different sizes.
void add_pressure_increment(std::span<double> pressure, std::span<const double> increment);

extern template class PressureSolver<1>;
extern template class PressureSolver<2>;
extern template class PressureSolver<3>;

}  // namespace ice

#pragma once

#include <mpi.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "ice/pressure/pressure_solver.hpp"
#include "ice/pressure/pressure_system_solver.hpp"

// The implicit pressure equation of the ICE step solved by PETSc over MPI
// ranks (issue 27): each rank assembles the rows of its own cells of a
// distributed structured grid (a DMDA over the same blocks as the solver's
// decomposition) and PETSc's conjugate gradients solve them together.
namespace ice::parallel {

struct PetscPressureOptions {
  // ||b - A dP|| / ||b|| to reach (PETSc's unpreconditioned CG residual).
  double tolerance = 1e-10;
  int max_iterations = 2000;
  // pfmg (hypre's structured multigrid on PETSc's MATHYPRESTRUCT, 2D and
  // 3D; a 2D grid is a 3D DMDA one cell thick), boomeramg (hypre's
  // algebraic multigrid), gamg (PETSc's smoothed-aggregation algebraic
  // multigrid) or jacobi. Measured on a 1e6-cell dam break (ice_mpi_bench,
  // one thread a rank): pfmg 17 iterations a solve and 1.03 s a step on one
  // rank, 0.58 s on two; boomeramg 9 iterations, 2.04 s and 1.27 s, most
  // of it its set-up, each solve; the built-in multigrid-preconditioned CG
  // on one rank 13 iterations and 0.56 s.
  std::string preconditioner = "boomeramg";
  // PETSc options for the solve, prefix ice_pressure_ (e.g.
  // "-ice_pressure_ksp_monitor -ice_pressure_pc_gamg_threshold 0.02").
  std::string petsc_options;
};

// The preconditioners PetscPressureOptions takes; throws std::invalid_argument otherwise.
void check_petsc_preconditioner(const std::string& name);

// PETSc refused PetscPressureOptions::petsc_options (an unknown value, a
// malformed string): what PETSc said. Callers name the case's key.
class PetscOptionsRefused : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// PETSc for the process: initialised by the first instance (on MPI as it
// stands, or starting it), finalised when the instance that initialised it
// ends. Keep it inside the MPI session. `world` is the communicator PETSc
// takes for its own (PETSC_COMM_WORLD): the ranks that initialise it
// together, when MPI runs already (else PETSc starts it for this process
// alone). A solver on one process inside a larger MPI job (a participant of
// an MPMD coupled run) passes MPI_COMM_SELF, so that PETSc waits for no
// other program.
class PetscLibrary {
 public:
  explicit PetscLibrary(MPI_Comm world = MPI_COMM_WORLD);
  ~PetscLibrary();
  PetscLibrary(const PetscLibrary&) = delete;
  PetscLibrary& operator=(const PetscLibrary&) = delete;

 private:
  bool initialised_here_ = false;
};

template <int Dim>
class PetscPressureSolver final : public PressureSystemSolver<Dim> {
 public:
  using Boundaries = typename PressureSolver<Dim>::Boundaries;
  using Offset = std::array<int, static_cast<std::size_t>(Dim)>;

  // `comm` holds decomposition.ranks() ranks, numbered as the decomposition
  // numbers its blocks; this rank's block is decomposition.block(rank).
  // `grid` is the whole grid, `boundaries` its sides; the fields given to
  // solve() belong to `block_grid`, whose first cell is cell `offset` of the
  // whole grid (the block widened by ghost layers). Collective. Throws
  // std::invalid_argument for options out of range and std::logic_error
  // when PETSc is not initialised (PetscLibrary).
  PetscPressureSolver(MPI_Comm comm,
                      const cosim::decomposition::CartesianDecomposition& decomposition,
                      const CellGrid<Dim>& grid, const Boundaries& boundaries,
                      const CellGrid<Dim>& block_grid, const Offset& offset,
                      PetscPressureOptions options);
  ~PetscPressureSolver() override;
  PetscPressureSolver(const PetscPressureSolver&) = delete;
  PetscPressureSolver& operator=(const PetscPressureSolver&) = delete;

  // Eq. 125 assembled over the owned cells and solved together (collective):
  // dP is written into the owned cells of `pressure_increment`, its ghosts
  // are left as they were.
  PressureSolution solve(std::span<const double> kappa, const FaceField<Dim>& face_density,
                         const FaceField<Dim>& predicted_velocity, double dt,
                         std::span<double> pressure_increment,
                         std::span<const double> volume_source) override;

 private:
  struct Petsc;  // the DMDA, matrix, vectors and KSP
  std::unique_ptr<Petsc> petsc_;
  CellGrid<Dim> grid_;
  Boundaries boundaries_;
  CellGrid<Dim> block_grid_;
  Offset offset_;
  PetscPressureOptions options_;
  std::array<std::array<int, 2>, static_cast<std::size_t>(Dim)> owned_{};  // in the whole grid
  bool unused_options_checked_ = false;                                    // after the first solve
};

extern template class PetscPressureSolver<1>;
extern template class PetscPressureSolver<2>;
extern template class PetscPressureSolver<3>;

}  // namespace ice::parallel

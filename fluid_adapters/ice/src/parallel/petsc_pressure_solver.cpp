#include "ice/parallel/petsc_pressure_solver.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <petscdmda.h>
#include <petscksp.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosim/error.hpp"

namespace ice::parallel {

namespace {

void check(PetscErrorCode code, const char* call) {
  if (code != 0) throw std::runtime_error(fmt::format("PETSc: {} failed (error {})", call, code));
}

// Keeps the first message of an error PETSc raises instead of printing it.
PetscErrorCode keep_first_message(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                                  PetscErrorType, const char* message, void* context) {
  auto* kept = static_cast<std::string*>(context);
  if (kept->empty() && message != nullptr) {
    *kept = message;
    kept->erase(kept->find_last_not_of(" \n") + 1);
  }
  return code;
}

// Runs a PETSc call that reads the user's options; its failure is
// PetscOptionsRefused with PETSc's own words.
template <class Call>
void apply_user_options(const std::string& options, Call call) {
  std::string message;
  PetscPushErrorHandler(keep_first_message, &message);
  const PetscErrorCode code = call();
  PetscPopErrorHandler();
  if (code != 0)
    throw PetscOptionsRefused(
        fmt::format("PETSc refused the options \"{}\": {}", options,
                    message.empty() ? fmt::format("error {}", code) : message));
}

// The options of the solve (prefix ice_pressure_) that PETSc has not read:
// misspelled, or for another preconditioner than the one chosen.
std::vector<std::string> unused_solve_options() {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  std::vector<std::string> unused;
  if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0) return unused;
  for (PetscInt i = 0; i < count; ++i) {
    const std::string name = names[i];
    if (name.rfind("ice_pressure_", 0) != 0) continue;
    unused.push_back("-" + name + (values[i] != nullptr ? std::string(" ") + values[i] : ""));
  }
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return unused;
}

}  // namespace

void check_petsc_preconditioner(const std::string& name) {
  if (name != "gamg" && name != "boomeramg" && name != "pfmg" && name != "jacobi")
    throw std::invalid_argument("unknown PETSc pressure preconditioner '" + name +
                                "' (known: pfmg, boomeramg, gamg, jacobi)");
}

PetscLibrary::PetscLibrary(MPI_Comm world) {
  PetscBool initialised = PETSC_FALSE;
  check(PetscInitialized(&initialised), "PetscInitialized");
  if (initialised) return;
  int mpi = 0;
  MPI_Initialized(&mpi);
  if (mpi != 0) PETSC_COMM_WORLD = world;  // else PETSc starts MPI, for this process alone
  // The run's own handlers stop it on SIGINT and SIGTERM (a clean stop,
  // outputs kept); PETSc's would abort it.
  check(PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr), "PetscOptionsSetValue");
  check(PetscInitializeNoArguments(), "PetscInitialize");
  initialised_here_ = true;
}

PetscLibrary::~PetscLibrary() {
  if (initialised_here_) PetscFinalize();
}

template <int Dim>
struct PetscPressureSolver<Dim>::Petsc {
  MPI_Comm comm = MPI_COMM_NULL;  // the ranks in the DMDA's order
  DM da = nullptr;
  Mat matrix = nullptr;
  Vec solution = nullptr, rhs = nullptr, residual = nullptr;
  KSP ksp = nullptr;
  ~Petsc() {
    KSPDestroy(&ksp);
    VecDestroy(&residual);
    VecDestroy(&rhs);
    VecDestroy(&solution);
    MatDestroy(&matrix);
    DMDestroy(&da);
    if (comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }
};

template <int Dim>
PetscPressureSolver<Dim>::PetscPressureSolver(
    MPI_Comm comm, const cosim::decomposition::CartesianDecomposition& decomposition,
    const CellGrid<Dim>& grid, const Boundaries& boundaries, const CellGrid<Dim>& block_grid,
    const Offset& offset, PetscPressureOptions options)
    : petsc_(std::make_unique<Petsc>()),
      grid_(grid),
      boundaries_(boundaries),
      block_grid_(block_grid),
      offset_(offset),
      options_(std::move(options)) {
  if (!(options_.tolerance > 0.0) || !std::isfinite(options_.tolerance))
    throw std::invalid_argument(
        fmt::format("PetscPressureSolver: tolerance must be positive, got {}", options_.tolerance));
  if (options_.max_iterations < 1)
    throw std::invalid_argument(fmt::format(
        "PetscPressureSolver: max_iterations must be at least 1, got {}", options_.max_iterations));
  check_petsc_preconditioner(options_.preconditioner);
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (!initialised) throw std::logic_error("PetscPressureSolver: PETSc is not initialised");
  if (decomposition.dimension() != Dim)
    throw std::invalid_argument("PetscPressureSolver: the decomposition's dimension differs");
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    if (decomposition.cells()[d] != grid.cells()[d])
      throw std::invalid_argument("PetscPressureSolver: the decomposition is of another grid");
  }

  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const cosim::decomposition::Block block = decomposition.block(rank);
  const std::array<int, 3> dims = decomposition.dims();
  // The DMDA numbers its ranks x fastest, the decomposition z fastest.
  const int key = block.coords[0] + dims[0] * (block.coords[1] + dims[1] * block.coords[2]);
  MPI_Comm_split(comm, 0, key, &petsc_->comm);
  std::array<std::vector<PetscInt>, 3> parts;
  std::array<PetscInt, 3> cells{1, 1, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    cells[d] = grid.cells()[d];
    for (int p = 0; p < dims[d]; ++p)
      parts[d].push_back(static_cast<PetscInt>(
          cosim::decomposition::even_range(grid.cells()[d], dims[d], p).size()));
    owned_[d] = {static_cast<int>(block.cells[d].begin), static_cast<int>(block.cells[d].end)};
    if (owned_[d][0] < offset[d] || owned_[d][1] > offset[d] + block_grid.cells()[d])
      throw std::invalid_argument("PetscPressureSolver: the block's grid does not hold its cells");
  }
  Petsc& p = *petsc_;
  // hypre's PFMG works on its structured matrix, which PETSc makes of a 3D
  // DMDA only: a plane is one cell thick.
  const bool pfmg = options_.preconditioner == "pfmg";
  if (pfmg && Dim == 1)
    throw std::invalid_argument("PetscPressureSolver: pfmg needs a 2D or 3D grid");
  if (pfmg && Dim == 2) {
    parts[2] = {1};
    check(DMDACreate3d(p.comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE,
                       DMDA_STENCIL_STAR, cells[0], cells[1], 1, dims[0], dims[1], 1, 1, 1,
                       parts[0].data(), parts[1].data(), parts[2].data(), &p.da),
          "DMDACreate3d");
  } else if constexpr (Dim == 1) {
    check(DMDACreate1d(p.comm, DM_BOUNDARY_NONE, cells[0], 1, 1, parts[0].data(), &p.da),
          "DMDACreate1d");
  } else if constexpr (Dim == 2) {
    check(DMDACreate2d(p.comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, cells[0],
                       cells[1], dims[0], dims[1], 1, 1, parts[0].data(), parts[1].data(), &p.da),
          "DMDACreate2d");
  } else {
    check(DMDACreate3d(p.comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE,
                       DMDA_STENCIL_STAR, cells[0], cells[1], cells[2], dims[0], dims[1], dims[2],
                       1, 1, parts[0].data(), parts[1].data(), parts[2].data(), &p.da),
          "DMDACreate3d");
  }
  check(DMSetUp(p.da), "DMSetUp");
  std::array<PetscInt, 3> first{}, size{};
  check(DMDAGetCorners(p.da, &first[0], &first[1], &first[2], &size[0], &size[1], &size[2]),
        "DMDAGetCorners");
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    if (first[d] != owned_[d][0] || first[d] + size[d] != owned_[d][1])
      throw std::logic_error("PetscPressureSolver: the DMDA's block differs from the solver's");
  }
  if (pfmg) check(DMSetMatType(p.da, MATHYPRESTRUCT), "DMSetMatType");
  check(DMCreateMatrix(p.da, &p.matrix), "DMCreateMatrix");
  if (!pfmg) check(MatSetOption(p.matrix, MAT_SPD, PETSC_TRUE), "MatSetOption");
  check(DMCreateGlobalVector(p.da, &p.solution), "DMCreateGlobalVector");
  check(VecDuplicate(p.solution, &p.rhs), "VecDuplicate");
  check(VecDuplicate(p.solution, &p.residual), "VecDuplicate");

  check(KSPCreate(p.comm, &p.ksp), "KSPCreate");
  check(KSPSetOptionsPrefix(p.ksp, "ice_pressure_"), "KSPSetOptionsPrefix");
  check(KSPSetType(p.ksp, KSPCG), "KSPSetType");
  PC pc = nullptr;
  check(KSPGetPC(p.ksp, &pc), "KSPGetPC");
  if (options_.preconditioner == "boomeramg") {
    check(PCSetType(pc, PCHYPRE), "PCSetType");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  } else if (pfmg) {
    check(PCSetType(pc, PCPFMG), "PCSetType");
  } else {
    check(PCSetType(pc, options_.preconditioner == "gamg" ? PCGAMG : PCJACOBI), "PCSetType");
  }
  // ||b - A x|| < tolerance ||b||, the built-in solver's rule.
  check(KSPSetTolerances(p.ksp, options_.tolerance, 0.0, static_cast<PetscReal>(PETSC_DEFAULT),
                         options_.max_iterations),
        "KSPSetTolerances");
  check(KSPSetNormType(p.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetInitialGuessNonzero(p.ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  const std::string& user = options_.petsc_options;
  if (!user.empty())
    apply_user_options(user, [&] { return PetscOptionsInsertString(nullptr, user.c_str()); });
  apply_user_options(user, [&] { return KSPSetFromOptions(p.ksp); });
}

template <int Dim>
PetscPressureSolver<Dim>::~PetscPressureSolver() = default;

// Tran et al., MPMICE, eq. 125 times V (PressureSolver states the rows).
template <int Dim>
PressureSolution PetscPressureSolver<Dim>::solve(std::span<const double> kappa,
                                                 const FaceField<Dim>& face_density,
                                                 const FaceField<Dim>& predicted_velocity,
                                                 double dt, std::span<double> pressure_increment,
                                                 std::span<const double> volume_source) {
  const auto cells = static_cast<std::size_t>(block_grid_.cell_count());
  if (kappa.size() != cells || pressure_increment.size() != cells ||
      (!volume_source.empty() && volume_source.size() != cells))
    throw std::invalid_argument("PetscPressureSolver: cell fields do not fit the block's grid");
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument(fmt::format("PetscPressureSolver: dt {} must be positive", dt));
  Petsc& p = *petsc_;
  const double volume = block_grid_.cell_volume();
  PetscScalar* rhs = nullptr;
  PetscScalar* guess = nullptr;
  check(VecGetArray(p.rhs, &rhs), "VecGetArray");
  check(VecGetArray(p.solution, &guess), "VecGetArray");
  std::array<int, 3> lo{0, 0, 0}, hi{1, 1, 1};
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    lo[d] = owned_[d][0];
    hi[d] = owned_[d][1];
  }
  std::size_t row_index = 0;  // the owned cells in the DMDA's order (x fastest)
  for (int k = lo[2]; k < hi[2]; ++k) {
    for (int j = lo[1]; j < hi[1]; ++j) {
      for (int i = lo[0]; i < hi[0]; ++i, ++row_index) {
        const std::array<int, 3> global{i, j, k};
        typename CellGrid<Dim>::CellIndex local{};
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
          local[d] = global[d] - offset_[d];
        const int c = block_grid_.cell(local);
        const double kappa_c = kappa[static_cast<std::size_t>(c)];
        if (!(kappa_c > 0.0) || !std::isfinite(kappa_c))
          throw std::invalid_argument(fmt::format(
              "PetscPressureSolver: kappa must be positive and finite, got {} in cell ({}, {}, {})",
              kappa_c, i, j, k));
        MatStencil row{};
        row.i = i;
        row.j = j;
        row.k = k;
        std::array<MatStencil, 2 * Dim + 1> columns{};
        std::array<PetscScalar, 2 * Dim + 1> values{};
        columns[0] = row;
        values[0] = kappa_c * volume / dt;
        int entries = 1;
        double b =
            volume_source.empty() ? 0.0 : -volume * volume_source[static_cast<std::size_t>(c)];
        for (int d = 0; d < Dim; ++d) {
          const auto du = static_cast<std::size_t>(d);
          const double area_over_spacing_dt =
              block_grid_.face_area(d) / block_grid_.spacing()[d] * dt;
          const int faces[2] = {block_grid_.lower_face(d, c), block_grid_.upper_face(d, c)};
          for (int side = 0; side < 2; ++side) {
            const double rho = face_density[du][static_cast<std::size_t>(faces[side])];
            const int neighbour = global[du] + (side == 0 ? -1 : 1);
            const bool interior = neighbour >= 0 && neighbour < grid_.cells()[du];
            const bool enters = interior || boundaries_[2 * du + static_cast<std::size_t>(side)] ==
                                                PressureBoundary::fixed_pressure;
            if (!enters) continue;
            if (!(rho > 0.0) || !std::isfinite(rho))
              throw std::invalid_argument(fmt::format(
                  "PetscPressureSolver: face density must be positive and finite, got {} on a "
                  "face of cell ({}, {}, {}) normal to direction {}",
                  rho, i, j, k, d));
            const double t = area_over_spacing_dt / rho;
            if (!interior) {
              values[0] += 2.0 * t;  // dP = 0 half a cell out
              continue;
            }
            values[0] += t;
            MatStencil column = row;
            (d == 0 ? column.i : d == 1 ? column.j : column.k) = neighbour;
            columns[static_cast<std::size_t>(entries)] = column;
            values[static_cast<std::size_t>(entries)] = -t;
            ++entries;
          }
          const std::vector<double>& u = predicted_velocity[du];
          const double u_lower = u[static_cast<std::size_t>(faces[0])];
          const double u_upper = u[static_cast<std::size_t>(faces[1])];
          if (!std::isfinite(u_lower) || !std::isfinite(u_upper))
            throw std::invalid_argument(
                "PetscPressureSolver: a predicted face velocity is not finite");
          b -= block_grid_.face_area(d) * (u_upper - u_lower);
        }
        check(MatSetValuesStencil(p.matrix, 1, &row, entries, columns.data(), values.data(),
                                  INSERT_VALUES),
              "MatSetValuesStencil");
        rhs[row_index] = b;
        guess[row_index] = pressure_increment[static_cast<std::size_t>(c)];
      }
    }
  }
  check(VecRestoreArray(p.solution, &guess), "VecRestoreArray");
  check(VecRestoreArray(p.rhs, &rhs), "VecRestoreArray");
  check(MatAssemblyBegin(p.matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(p.matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");

  PressureSolution result;
  PetscReal rhs_norm = 0.0;
  check(VecNorm(p.rhs, NORM_2, &rhs_norm), "VecNorm");
  if (rhs_norm == 0.0) {
    check(VecSet(p.solution, 0.0), "VecSet");
  } else {
    check(KSPSetOperators(p.ksp, p.matrix, p.matrix), "KSPSetOperators");
    check(KSPSolve(p.ksp, p.rhs, p.solution), "KSPSolve");
    PetscInt iterations = 0;
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetIterationNumber(p.ksp, &iterations), "KSPGetIterationNumber");
    check(KSPGetConvergedReason(p.ksp, &reason), "KSPGetConvergedReason");
    check(MatMult(p.matrix, p.solution, p.residual), "MatMult");
    check(VecAYPX(p.residual, -1.0, p.rhs), "VecAYPX");
    PetscReal residual_norm = 0.0;
    check(VecNorm(p.residual, NORM_2, &residual_norm), "VecNorm");
    result.iterations = static_cast<int>(iterations);
    result.relative_residual = residual_norm / rhs_norm;
    if (reason < 0 || !std::isfinite(result.relative_residual))
      throw cosim::NumericalError(fmt::format(
          "PETSc pressure solve (CG, {}): not converged after {} iterations (max_iterations {}): "
          "relative residual {:.3g}, tolerance {:.3g}, KSP reason {}",
          options_.preconditioner, result.iterations, options_.max_iterations,
          result.relative_residual, options_.tolerance, static_cast<int>(reason)));
  }
  if (!unused_options_checked_ && !options_.petsc_options.empty()) {
    unused_options_checked_ = true;
    if (const auto unused = unused_solve_options(); !unused.empty())
      spdlog::warn(
          "numerics.pressure.petsc_options: PETSc did not use {} (misspelled, or an option of "
          "another preconditioner than {})",
          fmt::join(unused, ", "), options_.preconditioner);
  }
  const PetscScalar* solution = nullptr;
  check(VecGetArrayRead(p.solution, &solution), "VecGetArrayRead");
  row_index = 0;
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i, ++row_index) {
        const std::array<int, 3> global{i, j, k};
        typename CellGrid<Dim>::CellIndex local{};
        for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
          local[d] = global[d] - offset_[d];
        pressure_increment[static_cast<std::size_t>(block_grid_.cell(local))] = solution[row_index];
      }
  check(VecRestoreArrayRead(p.solution, &solution), "VecRestoreArrayRead");
  return result;
}

template class PetscPressureSolver<1>;
template class PetscPressureSolver<2>;
template class PetscPressureSolver<3>;

}  // namespace ice::parallel

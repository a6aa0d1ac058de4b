#include "ice/pressure/pressure_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "ice/grid/face_walk.hpp"

namespace ice {

namespace {

void require_size(std::size_t size, int expected, const std::string& what) {
  if (size != static_cast<std::size_t>(expected)) {
    throw std::invalid_argument("PressureSolver: " + what + " has " + std::to_string(size) +
                                " values, the grid needs " + std::to_string(expected));
  }
}

template <int Dim>
void require_face_field_sizes(const CellGrid<Dim>& grid, const FaceField<Dim>& field,
                              const std::string& what) {
  for (int d = 0; d < Dim; ++d) {
    require_size(field[d].size(), grid.face_count(d),
                 what + " normal to direction " + std::to_string(d));
  }
}

void require_positive_time_step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("PressureSolver: dt must be positive and finite, got " +
                                std::to_string(dt));
  }
}

[[noreturn]] void throw_bad_density(double rho, int direction, int face) {
  throw std::invalid_argument("PressureSolver: face density must be positive and finite, got " +
                              std::to_string(rho) + " on face " + std::to_string(face) +
                              " normal to direction " + std::to_string(direction));
}

// Per face: the message is built out of line.
inline void require_positive_density(double rho, int direction, int face) {
  if (!(rho > 0.0) || !std::isfinite(rho)) throw_bad_density(rho, direction, face);
}

}  // namespace

PressureBoundary pressure_boundary_from_name(const std::string& name) {
  if (name == "wall") return PressureBoundary::wall;
  if (name == "fixed_pressure") return PressureBoundary::fixed_pressure;
  throw std::invalid_argument("unknown pressure boundary '" + name +
                              "' (known: wall, fixed_pressure)");
}

std::string to_string(PressureBoundary boundary) {
  return boundary == PressureBoundary::wall ? "wall" : "fixed_pressure";
}

PressurePreconditioner pressure_preconditioner_from_name(const std::string& name) {
  if (name == "jacobi") return PressurePreconditioner::jacobi;
  if (name == "incomplete_cholesky") return PressurePreconditioner::incomplete_cholesky;
  if (name == "multigrid") return PressurePreconditioner::multigrid;
  throw std::invalid_argument("unknown pressure preconditioner '" + name +
                              "' (known: jacobi, incomplete_cholesky, multigrid)");
}

std::string to_string(PressurePreconditioner preconditioner) {
  switch (preconditioner) {
    case PressurePreconditioner::jacobi:
      return "jacobi";
    case PressurePreconditioner::incomplete_cholesky:
      return "incomplete_cholesky";
    case PressurePreconditioner::multigrid:
      return "multigrid";
  }
  return "unknown";
}

template <int Dim>
PressureSolver<Dim>::PressureSolver(const CellGrid<Dim>& grid, const Boundaries& boundaries,
                                    PressureSolverOptions options)
    : grid_(grid), boundaries_(boundaries), options_(options) {
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    throw std::invalid_argument("PressureSolver: tolerance must be positive and finite, got " +
                                std::to_string(options.tolerance));
  }
  if (options.max_iterations < 1) {
    throw std::invalid_argument("PressureSolver: max_iterations must be at least 1, got " +
                                std::to_string(options.max_iterations));
  }
  const int n = grid.cell_count();
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(static_cast<std::size_t>(n) * (2 * Dim + 1));
  for (int c = 0; c < n; ++c) {
    pattern.emplace_back(c, c, 0.0);
  }
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const int lower = grid.lower_cell(d, f);
      const int upper = grid.upper_cell(d, f);
      if (lower >= 0 && upper >= 0) {
        pattern.emplace_back(lower, upper, 0.0);
        pattern.emplace_back(upper, lower, 0.0);
      }
    }
  }
  matrix_.resize(n, n);
  matrix_.setFromTriplets(pattern.begin(), pattern.end());
  matrix_.makeCompressed();

  const double* values = matrix_.valuePtr();
  const auto entry = [&](int row, int col) { return &matrix_.coeffRef(row, col) - values; };
  diagonal_entry_.resize(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    diagonal_entry_[c] = entry(c, c);
  }
  for (int d = 0; d < Dim; ++d) {
    face_cells_[d].resize(static_cast<std::size_t>(grid.face_count(d)));
    for (int f = 0; f < grid.face_count(d); ++f) {
      face_cells_[d][f] = {grid.lower_cell(d, f), grid.upper_cell(d, f)};
    }
    lower_upper_entry_[d].assign(static_cast<std::size_t>(grid.face_count(d)), -1);
    upper_lower_entry_[d].assign(static_cast<std::size_t>(grid.face_count(d)), -1);
    for (int f = 0; f < grid.face_count(d); ++f) {
      const int lower = grid.lower_cell(d, f);
      const int upper = grid.upper_cell(d, f);
      if (lower >= 0 && upper >= 0) {
        lower_upper_entry_[d][f] = entry(lower, upper);
        upper_lower_entry_[d][f] = entry(upper, lower);
      }
    }
  }
  right_hand_side_.resize(n);
  solution_.resize(n);
  if (options.preconditioner == PressurePreconditioner::multigrid) {
    typename MultigridPreconditioner<Dim>::Spacing spacing;
    for (int d = 0; d < Dim; ++d) spacing[d] = grid.spacing()[d];
    multigrid_ =
        std::make_unique<MultigridPreconditioner<Dim>>(grid.cells(), spacing, options.multigrid);
    for (Eigen::VectorXd* v : {&padded_rhs_, &padded_solution_, &padded_residual_,
                               &padded_preconditioned_, &padded_direction_, &padded_product_}) {
      *v = Eigen::VectorXd::Zero(multigrid_->padded_size());
    }
  } else {
    jacobi_cg_.analyzePattern(matrix_);
    cholesky_cg_.analyzePattern(matrix_);
  }
}

// Tran et al., MPMICE, eq. 125 times V: into the sparse matrix, or for the
// multigrid straight into its diagonal and couplings (T = -A_c,c+s), with the
// diagonal summed in the same order; matrix() then fills the sparse values
// from those when asked.
template <int Dim>
void PressureSolver<Dim>::assemble(std::span<const double> kappa,
                                   const FaceField<Dim>& face_density, double dt) {
  const double volume = grid_.cell_volume();
  for (int c = 0; c < grid_.cell_count(); ++c) {
    if (!(kappa[c] > 0.0) || !std::isfinite(kappa[c])) {
      throw std::invalid_argument("PressureSolver: kappa must be positive and finite, got " +
                                  std::to_string(kappa[c]) + " in cell " + std::to_string(c));
    }
  }
  require_entering_densities(face_density);
  if (multigrid_) {
    MultigridPreconditioner<Dim>& mg = *multigrid_;
    for (int c = 0; c < grid_.cell_count(); ++c) mg.diagonal(c) = kappa[c] * volume / dt;
    for (int d = 0; d < Dim; ++d) {
      const double area_over_spacing_dt = grid_.face_area(d) / grid_.spacing()[d] * dt;
      const std::vector<double>& rho = face_density[d];
      for_each_face(
          grid_, d,
          [&](int f, int lower, int upper) {
            const double t = area_over_spacing_dt / rho[f];
            mg.diagonal(lower) += t;
            mg.diagonal(upper) += t;
            mg.coupling(d, lower) = t;
          },
          [&](int f, int cell, bool upper_side) {
            if (boundaries_[2 * d + (upper_side ? 1 : 0)] != PressureBoundary::fixed_pressure) {
              return;
            }
            mg.diagonal(cell) += 2.0 * area_over_spacing_dt / rho[f];
          });
    }
    matrix_current_ = false;
    return;
  }
  double* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  for (int c = 0; c < grid_.cell_count(); ++c) values[diagonal_entry_[c]] = kappa[c] * volume / dt;
  for (int d = 0; d < Dim; ++d) {
    const double area_over_spacing_dt = grid_.face_area(d) / grid_.spacing()[d] * dt;
    const std::vector<double>& rho = face_density[d];
    for_each_face(
        grid_, d,
        [&](int f, int lower, int upper) {
          const double t = area_over_spacing_dt / rho[f];
          values[diagonal_entry_[lower]] += t;
          values[diagonal_entry_[upper]] += t;
          values[lower_upper_entry_[d][f]] -= t;
          values[upper_lower_entry_[d][f]] -= t;
        },
        [&](int f, int cell, bool upper_side) {
          if (boundaries_[2 * d + (upper_side ? 1 : 0)] != PressureBoundary::fixed_pressure) return;
          values[diagonal_entry_[cell]] += 2.0 * area_over_spacing_dt / rho[f];
        });
  }
}

template <int Dim>
const Eigen::SparseMatrix<double>& PressureSolver<Dim>::matrix() const {
  if (!matrix_current_) {
    // The multigrid's operator as the sparse values: A_cc = D_c,
    // A_c,c+s = A_c+s,c = -T (0 - T, as the sparse assembly forms it).
    const MultigridPreconditioner<Dim>& mg = *multigrid_;
    double* values = matrix_.valuePtr();
    for (int c = 0; c < grid_.cell_count(); ++c) values[diagonal_entry_[c]] = mg.diagonal(c);
    for (int d = 0; d < Dim; ++d) {
      for (int f = 0; f < grid_.face_count(d); ++f) {
        if (lower_upper_entry_[d][f] < 0) continue;
        const double t = mg.coupling(d, face_cells_[d][f][0]);
        values[lower_upper_entry_[d][f]] = 0.0 - t;
        values[upper_lower_entry_[d][f]] = 0.0 - t;
      }
    }
    matrix_current_ = true;
  }
  return matrix_;
}

// -V (div_c U*_FC + source_c).
template <int Dim>
void PressureSolver<Dim>::set_right_hand_side(const FaceField<Dim>& predicted_velocity,
                                              std::span<const double> volume_source) {
  right_hand_side_.setZero();
  if (!volume_source.empty()) {
    const double volume = grid_.cell_volume();
    for (std::size_t c = 0; c < volume_source.size(); ++c) {
      if (!std::isfinite(volume_source[c])) {
        throw std::invalid_argument("PressureSolver: volume source is not finite in cell " +
                                    std::to_string(c));
      }
      right_hand_side_[static_cast<Eigen::Index>(c)] = -volume * volume_source[c];
    }
  }
  for (int d = 0; d < Dim; ++d) {
    const double area = grid_.face_area(d);
    const std::vector<double>& u = predicted_velocity[d];
    for (int f = 0; f < grid_.face_count(d); ++f) {
      if (!std::isfinite(u[f])) {
        throw std::invalid_argument(
            "PressureSolver: predicted face velocity is not finite on face " + std::to_string(f) +
            " normal to direction " + std::to_string(d));
      }
    }
    for_each_row(grid_, [&](int first, int length) {
      const double* lower = u.data() + lower_face_offset(grid_, d, first);
      const double* upper = lower + grid_.stride(d);
      for (int c = first; c < first + length; ++c) {
        right_hand_side_[c] -= area * (upper[c] - lower[c]);
      }
    });
  }
}

template <int Dim>
template <class Solver>
PressureSolution PressureSolver<Dim>::run(Solver& solver, std::span<double> pressure_increment) {
  solver.setTolerance(options_.tolerance);
  solver.setMaxIterations(options_.max_iterations);
  solver.factorize(matrix_);
  if (solver.info() != Eigen::Success) {
    throw cosim::NumericalError(
        "PressureSolver: the preconditioner could not be built for the pressure matrix");
  }
  const Eigen::Map<Eigen::VectorXd> guess(pressure_increment.data(),
                                          static_cast<Eigen::Index>(pressure_increment.size()));
  solution_ = solver.solveWithGuess(right_hand_side_, guess);
  PressureSolution result;
  result.iterations = static_cast<int>(solver.iterations());
  const double rhs_norm = right_hand_side_.norm();
  result.relative_residual =
      rhs_norm > 0.0 ? (right_hand_side_ - matrix_ * solution_).norm() / rhs_norm : 0.0;
  const bool converged = solver.info() == Eigen::Success && std::isfinite(result.relative_residual);
  if (!converged) throw_not_converged(result);
  std::copy(solution_.begin(), solution_.end(), pressure_increment.begin());
  return result;
}

template <int Dim>
void PressureSolver<Dim>::throw_not_converged(const PressureSolution& result) const {
  std::ostringstream message;
  message << "PressureSolver: conjugate gradients did not converge in " << result.iterations
          << " iterations (max_iterations " << options_.max_iterations << "): relative residual "
          << result.relative_residual << ", tolerance " << options_.tolerance;
  throw cosim::NumericalError(message.str());
}

// Preconditioned conjugate gradients (as Eigen's, same stopping rule on the
// recurrence residual) in the multigrid's padded layout; on reaching the
// tolerance the residual is recomputed and the iteration restarted from it
// if recurrence drift left it above the tolerance.
template <int Dim>
PressureSolution PressureSolver<Dim>::run_multigrid(std::span<double> pressure_increment) {
  MultigridPreconditioner<Dim>& mg = *multigrid_;
  mg.update();  // assemble() wrote its finest operator

  const Eigen::Index n = grid_.cell_count();
  const Eigen::Index p = mg.padding();
  auto b = padded_rhs_.segment(p, n);
  auto x = padded_solution_.segment(p, n);
  auto r = padded_residual_.segment(p, n);
  auto z = padded_preconditioned_.segment(p, n);
  auto s = padded_direction_.segment(p, n);
  auto q = padded_product_.segment(p, n);
  b = right_hand_side_;
  x = Eigen::Map<const Eigen::VectorXd>(pressure_increment.data(), n);
  PressureSolution result;
  const double rhs_norm2 = b.squaredNorm();
  if (rhs_norm2 == 0.0) {
    std::fill(pressure_increment.begin(), pressure_increment.end(), 0.0);
    return result;
  }
  const double threshold2 = options_.tolerance * options_.tolerance * rhs_norm2;
  const auto true_residual2 = [&] {
    mg.multiply(padded_solution_, padded_product_);
    r = b - q;
    return r.squaredNorm();
  };
  double residual2 = true_residual2();
  while (!(residual2 < threshold2) && result.iterations < options_.max_iterations) {
    mg.apply(padded_residual_, padded_preconditioned_);
    double rz = r.dot(z);
    s = z;
    mg.multiply(padded_direction_, padded_product_);
    while (result.iterations < options_.max_iterations) {
      const double step = rz / s.dot(q);
      // x += step s and r -= step q in one pass.
      double* xv = x.data();
      double* rv = r.data();
      const double* sv = s.data();
      const double* qv = q.data();
      for (Eigen::Index c = 0; c < n; ++c) {
        xv[c] += step * sv[c];
        rv[c] -= step * qv[c];
      }
      ++result.iterations;
      if (!(r.squaredNorm() >= threshold2)) break;
      mg.apply(padded_residual_, padded_preconditioned_);
      const double rz_next = r.dot(z);
      // s = z + beta s and q = A s of the next iteration, in one pass.
      mg.update_and_multiply(padded_preconditioned_, rz_next / rz, padded_direction_,
                             padded_product_);
      rz = rz_next;
    }
    residual2 = true_residual2();
  }
  result.relative_residual = std::sqrt(residual2 / rhs_norm2);
  if (!(residual2 < threshold2)) throw_not_converged(result);
  std::copy(x.begin(), x.end(), pressure_increment.begin());
  return result;
}

template <int Dim>
PressureSolution PressureSolver<Dim>::solve(std::span<const double> kappa,
                                            const FaceField<Dim>& face_density,
                                            const FaceField<Dim>& predicted_velocity, double dt,
                                            std::span<double> pressure_increment,
                                            std::span<const double> volume_source) {
  require_size(kappa.size(), grid_.cell_count(), "kappa");
  require_size(pressure_increment.size(), grid_.cell_count(), "pressure increment");
  if (!volume_source.empty())
    require_size(volume_source.size(), grid_.cell_count(), "volume source");
  require_face_field_sizes(grid_, face_density, "face density");
  require_face_field_sizes(grid_, predicted_velocity, "predicted face velocity");
  require_positive_time_step(dt);
  for (const double guess : pressure_increment) {
    if (!std::isfinite(guess)) {
      throw std::invalid_argument("PressureSolver: initial pressure increment is not finite");
    }
  }
  assemble(kappa, face_density, dt);
  set_right_hand_side(predicted_velocity, volume_source);
  switch (options_.preconditioner) {
    case PressurePreconditioner::jacobi:
      return run(jacobi_cg_, pressure_increment);
    case PressurePreconditioner::incomplete_cholesky:
      return run(cholesky_cg_, pressure_increment);
    case PressurePreconditioner::multigrid:
      break;
  }
  return run_multigrid(pressure_increment);
}

template <int Dim>
void PressureSolver<Dim>::correct_face_velocities(const FaceField<Dim>& face_density,
                                                  std::span<const double> pressure_increment,
                                                  double dt, FaceField<Dim>& face_velocity) const {
  require_size(pressure_increment.size(), grid_.cell_count(), "pressure increment");
  require_face_field_sizes(grid_, face_density, "face density");
  require_face_field_sizes(grid_, face_velocity, "face velocity");
  require_positive_time_step(dt);
  require_entering_densities(face_density);
  for (int d = 0; d < Dim; ++d) {
    const double dx = grid_.spacing()[d];
    const double* rho = face_density[d].data();
    double* u = face_velocity[d].data();
    const double* dp = pressure_increment.data();
    for_each_face(
        grid_, d,
        [&](int f, int lower, int upper) {
          const double gradient = (dp[upper] - dp[lower]) / dx;
          u[f] -= dt / rho[f] * gradient;
        },
        [&](int f, int cell, bool upper_side) {
          if (boundaries_[2 * d + (upper_side ? 1 : 0)] != PressureBoundary::fixed_pressure) return;
          const double gradient = upper_side ? -dp[cell] / (0.5 * dx) : dp[cell] / (0.5 * dx);
          u[f] -= dt / rho[f] * gradient;
        });
  }
}

// Every face density that enters (interior and fixed_pressure faces) is
// positive and finite; otherwise the first bad one, in face order, is
// reported. A branch-free pass, so the loops using them need no check.
namespace {

// How many of values[first, end) are not positive and finite, i.e. not
// 0 < value <= the largest double (NaN fails both): comparisons only,
// combined without a branch, counted in a double (exact to 2^53; GCC
// vectorises this reduction, not one into an integer), so that the loop
// vectorises.
double count_not_positive_finite(const double* __restrict values, int first, int end) {
  constexpr double largest = std::numeric_limits<double>::max();
  double bad = 0.0;
  for (int f = first; f < end; ++f) bad += (values[f] > 0.0) & (values[f] <= largest) ? 0.0 : 1.0;
  return bad;
}

}  // namespace

template <int Dim>
void PressureSolver<Dim>::require_entering_densities(const FaceField<Dim>& face_density) const {
  double bad = 0.0;
  for (int d = 0; d < Dim; ++d) {
    const double* rho = face_density[d].data();
    const auto is_bad = [](double value) {
      return !(value > 0.0 && value <= std::numeric_limits<double>::max());
    };
    for_each_face_run(
        grid_, d,
        [&](int first, int end, int) { bad += count_not_positive_finite(rho, first, end); },
        [&](int f, int, bool upper_side) {
          if (boundaries_[2 * d + (upper_side ? 1 : 0)] == PressureBoundary::fixed_pressure) {
            bad += is_bad(rho[f]) ? 1.0 : 0.0;
          }
        });
  }
  if (bad == 0.0) return;
  for (int d = 0; d < Dim; ++d) {
    const std::vector<double>& rho = face_density[d];
    for_each_face(
        grid_, d, [&](int f, int, int) { require_positive_density(rho[f], d, f); },
        [&](int f, int, bool upper_side) {
          if (boundaries_[2 * d + (upper_side ? 1 : 0)] == PressureBoundary::fixed_pressure) {
            require_positive_density(rho[f], d, f);
          }
        });
  }
}

void add_pressure_increment(std::span<double> pressure, std::span<const double> increment) {
  if (pressure.size() != increment.size()) {
    throw std::invalid_argument("add_pressure_increment: pressure has " +
                                std::to_string(pressure.size()) + " values, the increment " +
                                std::to_string(increment.size()));
  }
  for (std::size_t c = 0; c < pressure.size(); ++c) {
    pressure[c] += increment[c];
  }
}

template class PressureSolver<1>;
template class PressureSolver<2>;
template class PressureSolver<3>;

}  // namespace ice

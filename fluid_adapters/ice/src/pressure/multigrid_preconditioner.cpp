#include "ice/pressure/multigrid_preconditioner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosim/error.hpp"

namespace ice {

namespace {

void require_options(const MultigridOptions& options) {
  if (options.smoothing_sweeps < 1 || options.cycle < 1 || options.cycle > 2 ||
      options.coarsest_cells < 1 || !(options.coupling_scale > 0.0) ||
      !(options.coupling_scale <= 1.0) || !(options.correction_scale > 0.0) ||
      !std::isfinite(options.correction_scale)) {
    throw std::invalid_argument(
        "MultigridPreconditioner: need smoothing_sweeps >= 1, cycle 1 or 2, coarsest_cells >= 1, "
        "0 < coupling_scale <= 1 and a positive finite correction_scale");
  }
}

}  // namespace

template <int Dim>
typename MultigridPreconditioner<Dim>::Level MultigridPreconditioner<Dim>::make_level(
    const CellCounts& cells) {
  Level level;
  level.cells = cells;
  level.cell_count = 1;
  for (int d = 0; d < Dim; ++d) {
    if (cells[d] < 1) {
      throw std::invalid_argument("MultigridPreconditioner: cell count " +
                                  std::to_string(cells[d]) + " along direction " +
                                  std::to_string(d) + " is below one");
    }
    level.stride[d] = level.cell_count;
    level.cell_count *= cells[d];
  }
  level.padding = level.stride[Dim - 1];
  const Eigen::Index size = level.cell_count + 2 * level.padding;
  level.diagonal = Eigen::VectorXd::Zero(size);
  level.inverse_diagonal = Eigen::VectorXd::Zero(size);
  level.lower_weight = Eigen::VectorXd::Zero(size);
  level.upper_weight = Eigen::VectorXd::Zero(size);
  level.surplus = Eigen::VectorXd::Zero(size);
  for (auto& coupling : level.coupling) coupling = Eigen::VectorXd::Zero(size);
  level.solution = Eigen::VectorXd::Zero(size);
  level.right_hand_side = Eigen::VectorXd::Zero(size);
  level.residual = Eigen::VectorXd::Zero(size);
  return level;
}

template <int Dim>
MultigridPreconditioner<Dim>::MultigridPreconditioner(const CellCounts& cells,
                                                      const Spacing& spacing,
                                                      MultigridOptions options)
    : options_(options) {
  require_options(options);
  for (int d = 0; d < Dim; ++d) {
    if (!(spacing[d] > 0.0) || !std::isfinite(spacing[d])) {
      throw std::invalid_argument("MultigridPreconditioner: spacing " + std::to_string(spacing[d]) +
                                  " along direction " + std::to_string(d) +
                                  " is not positive and finite");
    }
  }
  levels_.push_back(make_level(cells));
  Spacing h = spacing;
  while (levels_.back().cell_count > options.coarsest_cells) {
    Level& fine = levels_.back();
    double smallest = std::numeric_limits<double>::infinity();
    for (int d = 0; d < Dim; ++d) {
      if (fine.cells[d] > 1) smallest = std::min(smallest, h[d]);
    }
    CellCounts coarse_cells = fine.cells;
    for (int d = 0; d < Dim; ++d) {
      fine.coarsened[d] = fine.cells[d] > 1 && h[d] < 2.0 * smallest;
      if (fine.coarsened[d]) {
        coarse_cells[d] = (fine.cells[d] + 1) / 2;
        h[d] *= 2.0;
      }
    }
    if (coarse_cells == fine.cells) break;
    Level coarse = make_level(coarse_cells);
    fine.aggregate.resize(static_cast<std::size_t>(fine.cell_count));
    for (int c = 0; c < fine.cell_count; ++c) {
      int coarse_cell = 0;
      for (int d = 0; d < Dim; ++d) {
        const int i = (c / fine.stride[d]) % fine.cells[d];
        coarse_cell += (fine.coarsened[d] ? i / 2 : i) * coarse.stride[d];
      }
      fine.aggregate[static_cast<std::size_t>(c)] = coarse_cell;
    }
    levels_.push_back(std::move(coarse));
  }
  const Eigen::Index m = levels_.back().cell_count;
  coarsest_matrix_ = Eigen::MatrixXd::Identity(m, m);
  coarsest_vector_ = Eigen::VectorXd::Zero(m);
  coarsest_factor_.compute(coarsest_matrix_);  // sizes its storage once
}

// P^T A P with P piecewise constant: the row sums (kappa V / dt and the
// fixed-pressure ghosts) add up, couplings across an aggregate face add up
// (then scaled), couplings inside an aggregate drop out.
template <int Dim>
void MultigridPreconditioner<Dim>::build_coarse_operator(int level) {
  const Level& fine = levels_[static_cast<std::size_t>(level)];
  Level& coarse = levels_[static_cast<std::size_t>(level) + 1];
  const int pf = fine.padding;
  const int pc = coarse.padding;
  const int n = fine.cell_count;
  const int* aggregate = fine.aggregate.data();
  coarse.surplus.setZero();
  for (int c = 0; c < n; ++c) coarse.surplus[pc + aggregate[c]] += fine.surplus[pf + c];
  for (int d = 0; d < Dim; ++d) {
    const int s = fine.stride[d];
    const double* t = fine.coupling[d].data() + pf;
    double* coarse_t = coarse.coupling[d].data() + pc;
    coarse.coupling[d].setZero();
    for (int c = 0; c + s < n; ++c) {
      if (aggregate[c] != aggregate[c + s]) coarse_t[aggregate[c]] += t[c];
    }
    if (fine.coarsened[d]) coarse.coupling[d] *= options_.coupling_scale;
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::set_diagonal_from_couplings(Level& level) {
  const int p = level.padding;
  const int n = level.cell_count;
  auto diagonal = level.diagonal.segment(p, n);
  diagonal = level.surplus.segment(p, n);
  for (int d = 0; d < Dim; ++d) {
    const int s = level.stride[d];
    diagonal += level.coupling[d].segment(p, n) + level.coupling[d].segment(p - s, n);
  }
  set_inverse_diagonal(level);
}

template <int Dim>
void MultigridPreconditioner<Dim>::set_inverse_diagonal(Level& level) {
  const int p = level.padding;
  const int n = level.cell_count;
  level.inverse_diagonal.segment(p, n) = level.diagonal.segment(p, n).cwiseInverse();
  level.lower_weight.segment(p, n) =
      level.coupling[0].segment(p - 1, n).cwiseProduct(level.inverse_diagonal.segment(p, n));
  level.upper_weight.segment(p, n) =
      level.coupling[0].segment(p, n).cwiseProduct(level.inverse_diagonal.segment(p, n));
}

template <int Dim>
void MultigridPreconditioner<Dim>::update() {
  Level& finest = levels_.front();
  const int p = finest.padding;
  const int n = finest.cell_count;
  finest.surplus.segment(p, n) = finest.diagonal.segment(p, n);
  for (int d = 0; d < Dim; ++d) {
    const int s = finest.stride[d];
    finest.surplus.segment(p, n) -=
        finest.coupling[d].segment(p, n) + finest.coupling[d].segment(p - s, n);
  }
  set_inverse_diagonal(finest);
  for (int level = 0; level + 1 < level_count(); ++level) {
    build_coarse_operator(level);
    set_diagonal_from_couplings(levels_[static_cast<std::size_t>(level) + 1]);
  }
  const Level& coarsest = levels_.back();
  const int pc = coarsest.padding;
  coarsest_matrix_.setZero();
  for (int c = 0; c < coarsest.cell_count; ++c) {
    coarsest_matrix_(c, c) = coarsest.diagonal[pc + c];
    for (int d = 0; d < Dim; ++d) {
      const double t = coarsest.coupling[d][pc + c];
      if (t != 0.0) {
        coarsest_matrix_(c, c + coarsest.stride[d]) = -t;
        coarsest_matrix_(c + coarsest.stride[d], c) = -t;
      }
    }
  }
  coarsest_factor_.compute(coarsest_matrix_);
  if (coarsest_factor_.info() != Eigen::Success) {
    throw cosim::NumericalError(
        "MultigridPreconditioner: the coarsest pressure operator is not positive definite");
  }
}

template <int Dim>
Eigen::SparseMatrix<double> MultigridPreconditioner<Dim>::level_operator(int level) const {
  const Level& l = levels_.at(static_cast<std::size_t>(level));
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < l.cell_count; ++c) {
    entries.emplace_back(c, c, l.diagonal[l.padding + c]);
    for (int d = 0; d < Dim; ++d) {
      const double t = l.coupling[d][l.padding + c];
      if (t != 0.0) {
        entries.emplace_back(c, c + l.stride[d], -t);
        entries.emplace_back(c + l.stride[d], c, -t);
      }
    }
  }
  Eigen::SparseMatrix<double> a(l.cell_count, l.cell_count);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

template <int Dim>
void MultigridPreconditioner<Dim>::multiply(const Level& level, const Eigen::VectorXd& x,
                                            Eigen::VectorXd& y) {
  const int p = level.padding;
  const int n = level.cell_count;
  auto out = y.segment(p, n);
  out = level.diagonal.segment(p, n).cwiseProduct(x.segment(p, n));
  for (int d = 0; d < Dim; ++d) {
    const int s = level.stride[d];
    out -= level.coupling[d].segment(p, n).cwiseProduct(x.segment(p + s, n)) +
           level.coupling[d].segment(p - s, n).cwiseProduct(x.segment(p - s, n));
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  multiply(levels_.front(), x, y);
}

// Gauss-Seidel row by row along x: the terms of the neighbours off the row
// (the previous rows already updated, the next ones not) and of the
// not-yet-updated neighbour along the row are summed vectorised; what is
// left is the recurrence x_c = y_c + (T_0,c-1 / D_c) x_c-1 along the row.
template <int Dim>
void MultigridPreconditioner<Dim>::forward_gauss_seidel(Level& level, const Eigen::VectorXd& b,
                                                        Eigen::VectorXd& x) {
  const int p = level.padding;
  const int nx = level.cells[0];
  double* scratch = level.residual.data();
  const double* weight = level.lower_weight.data();
  double* v = x.data();
  for (int row = p; row < p + level.cell_count; row += nx) {
    auto y = level.residual.segment(row, nx);
    y = b.segment(row, nx) +
        level.coupling[0].segment(row, nx).cwiseProduct(x.segment(row + 1, nx));
    for (int d = 1; d < Dim; ++d) {
      const int s = level.stride[d];
      y += level.coupling[d].segment(row, nx).cwiseProduct(x.segment(row + s, nx)) +
           level.coupling[d].segment(row - s, nx).cwiseProduct(x.segment(row - s, nx));
    }
    y = y.cwiseProduct(level.inverse_diagonal.segment(row, nx));
    for (int c = row; c < row + nx; ++c) v[c] = scratch[c] + weight[c] * v[c - 1];
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::backward_gauss_seidel(Level& level, const Eigen::VectorXd& b,
                                                         Eigen::VectorXd& x) {
  const int p = level.padding;
  const int nx = level.cells[0];
  double* scratch = level.residual.data();
  const double* weight = level.upper_weight.data();
  double* v = x.data();
  for (int row = p + level.cell_count - nx; row >= p; row -= nx) {
    auto y = level.residual.segment(row, nx);
    y = b.segment(row, nx) +
        level.coupling[0].segment(row - 1, nx).cwiseProduct(x.segment(row - 1, nx));
    for (int d = 1; d < Dim; ++d) {
      const int s = level.stride[d];
      y += level.coupling[d].segment(row, nx).cwiseProduct(x.segment(row + s, nx)) +
           level.coupling[d].segment(row - s, nx).cwiseProduct(x.segment(row - s, nx));
    }
    y = y.cwiseProduct(level.inverse_diagonal.segment(row, nx));
    for (int c = row + nx - 1; c >= row; --c) v[c] = scratch[c] + weight[c] * v[c + 1];
  }
}

// Solves level `level` approximately for its right_hand_side from a zero
// solution: smoothing, coarse correction and smoothing, `cycle` times.
template <int Dim>
void MultigridPreconditioner<Dim>::cycle(int level) {
  Level& fine = levels_[static_cast<std::size_t>(level)];
  const int pf = fine.padding;
  const int n = fine.cell_count;
  if (level + 1 == level_count()) {
    coarsest_vector_ = fine.right_hand_side.segment(pf, n);
    coarsest_factor_.solveInPlace(coarsest_vector_);
    fine.solution.segment(pf, n) = coarsest_vector_;
    return;
  }
  Level& coarse = levels_[static_cast<std::size_t>(level) + 1];
  const int pc = coarse.padding;
  const int* aggregate = fine.aggregate.data();
  fine.solution.setZero();
  for (int visit = 0; visit < options_.cycle; ++visit) {
    for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep) {
      forward_gauss_seidel(fine, fine.right_hand_side, fine.solution);
    }
    multiply(fine, fine.solution, fine.residual);
    fine.residual.segment(pf, n) =
        fine.right_hand_side.segment(pf, n) - fine.residual.segment(pf, n);
    coarse.right_hand_side.setZero();
    for (int c = 0; c < n; ++c) {
      coarse.right_hand_side[pc + aggregate[c]] += fine.residual[pf + c];
    }
    cycle(level + 1);
    const double scale = options_.correction_scale;
    for (int c = 0; c < n; ++c) {
      fine.solution[pf + c] += scale * coarse.solution[pc + aggregate[c]];
    }
    for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep) {
      backward_gauss_seidel(fine, fine.right_hand_side, fine.solution);
    }
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  Level& finest = levels_.front();
  const int p = finest.padding;
  const int n = finest.cell_count;
  finest.right_hand_side.segment(p, n) = r.segment(p, n);
  cycle(0);
  z.segment(p, n) = finest.solution.segment(p, n);
}

template class MultigridPreconditioner<1>;
template class MultigridPreconditioner<2>;
template class MultigridPreconditioner<3>;

}  // namespace ice

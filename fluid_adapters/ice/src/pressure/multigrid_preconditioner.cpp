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
  level.surplus = Eigen::VectorXd::Zero(size);
  for (auto& coupling : level.coupling) coupling = Eigen::VectorXd::Zero(size);
  level.solution = Eigen::VectorXd::Zero(size);
  level.row = Eigen::VectorXd::Zero(cells[0]);
  level.right_hand_side = Eigen::VectorXd::Zero(size);
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
  // One pass: D_c x_c, then minus each direction's pair of couplings.
  const int p = level.padding;
  const int n = level.cell_count;
  const double* diagonal = level.diagonal.data() + p;
  const double* v = x.data() + p;
  double* out = y.data() + p;
  std::array<const double*, Dim> t{};
  std::array<int, Dim> stride{};
  for (int d = 0; d < Dim; ++d) {
    t[d] = level.coupling[d].data() + p;
    stride[d] = level.stride[d];
  }
  for (int c = 0; c < n; ++c) {
    double product = diagonal[c] * v[c];
    for (int d = 0; d < Dim; ++d) {
      const int s = stride[d];
      product -= t[d][c] * v[c + s] + t[d][c - s] * v[c - s];
    }
    out[c] = product;
  }
}

// s = z + beta s, then y = A s, in one pass: the product runs a stencil
// reach (the largest stride, the padding) behind the update, in chunks, so
// that it reads only updated directions, still in cache. The operations are
// those of the two separate steps.
template <int Dim>
void MultigridPreconditioner<Dim>::update_and_multiply(const Eigen::VectorXd& z, double beta,
                                                       Eigen::VectorXd& s,
                                                       Eigen::VectorXd& y) const {
  const Level& level = levels_.front();
  const int p = level.padding;
  const int n = level.cell_count;
  const int reach = level.padding;
  constexpr int chunk = 1024;
  const double* zv = z.data() + p;
  double* sv = s.data() + p;
  double* out = y.data() + p;
  const double* diagonal = level.diagonal.data() + p;
  std::array<const double*, Dim> t{};
  std::array<int, Dim> stride{};
  for (int d = 0; d < Dim; ++d) {
    t[d] = level.coupling[d].data() + p;
    stride[d] = level.stride[d];
  }
  for (int lead = 0; lead < n + reach; lead += chunk) {
    const int update_end = std::min(lead + chunk, n);
    for (int c = lead; c < update_end; ++c) sv[c] = zv[c] + beta * sv[c];
    const int product_begin = std::max(lead - reach, 0);
    const int product_end = std::min(lead + chunk - reach, n);
    for (int c = product_begin; c < product_end; ++c) {
      double product = diagonal[c] * sv[c];
      for (int d = 0; d < Dim; ++d) {
        const int sd = stride[d];
        product -= t[d][c] * sv[c + sd] + t[d][c - sd] * sv[c - sd];
      }
      out[c] = product;
    }
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  multiply(levels_.front(), x, y);
}

// Gauss-Seidel, the rows along x in lexicographic order (forward) or its
// reverse (backward). Cell c takes
//
//   forward:  x_c = (b_c + T_0,c x_c+1 + sum_d>0 (T_d,c x_c+s_d + T_d,c-s_d x_c-s_d)) / D_c
//                   + (T_0,c-1 / D_c) x_c-1,
//   backward: the same with T_0,c-1 x_c-1 in the sum and (T_0,c / D_c) x_c+1 after it,
//
// the neighbours before c in the sweep order already updated, those after
// it not. Along a row this is a recurrence whose multiply-add latency, not
// the arithmetic, bounded the one-row-at-a-time sweep; so `kBlockRows`
// consecutive rows are swept together as a wavefront, row k of the block
// kLag * k cells behind row k - 1: each cell still sees exactly the
// neighbour values the row-by-row order gives it (the row before is
// kLag cells ahead, the row after kLag behind), so the result is the same
// to the bit, while the rows' recurrences overlap. The operations keep the
// order of the former vectorised form ((b + T_0 x) + sum_d (T x + T x)) / D.
namespace {

constexpr int kBlockRows = 2;
constexpr int kLag = 6;

template <int Dim>
struct SweepOperator {
  std::array<const double*, Dim> coupling;
  std::array<int, Dim> stride;
  const double* inverse_diagonal;
};

// `along` is the value of the row neighbour already updated (x_c-1 forward,
// x_c+1 backward); its weight T_0 / D is formed here rather than stored, so
// that a sweep streams one array fewer.
//
// from_zero: the first forward sweep from x = 0, where the neighbours not yet
// updated are exactly 0 and each T x of theirs is +0 (T finite >= 0): the
// additions of +0 are kept, so the result is the same to the bit without
// reading them.
template <int Dim, bool forward, bool from_zero>
inline double updated_value(const SweepOperator<Dim>& a, const double* b, const double* x, int c,
                            double along) {
  const double* t0 = a.coupling[0];
  double y = from_zero ? b[c] + 0.0
             : forward ? b[c] + t0[c] * x[c + 1]
                       : b[c] + t0[c - 1] * x[c - 1];
  for (int d = 1; d < Dim; ++d) {
    const int s = a.stride[d];
    if constexpr (from_zero) {
      y += 0.0 + a.coupling[d][c - s] * x[c - s];
    } else {
      y += a.coupling[d][c] * x[c + s] + a.coupling[d][c - s] * x[c - s];
    }
  }
  const double weight = (forward ? t0[c - 1] : t0[c]) * a.inverse_diagonal[c];
  return y * a.inverse_diagonal[c] + weight * along;
}

// Rows `first_row` .. + Rows - 1 (forward) or `first_row` .. - (Rows - 1)
// (backward) of nx cells; first_row is the padded index of a row's first
// cell. At step t row k updates its cell t - kLag k in sweep order, which is
// cell start(t) +- k (nx - kLag): one index per step. A row's first cell in
// sweep order has weight 0 (no neighbour along x beyond the row end), so its
// recurrence starts from 0.
template <int Dim, bool forward, bool from_zero, int Rows>
void sweep_rows(const SweepOperator<Dim>& a, const double* b, double* x, int first_row, int nx) {
  std::array<double, Rows> along{};
  const int delta = forward ? nx - kLag : kLag - nx;
  const auto update = [&](int t, int k) {
    const int c = (forward ? first_row + t : first_row + nx - 1 - t) + k * delta;
    along[k] = x[c] = updated_value<Dim, forward, from_zero>(a, b, x, c, along[k]);
  };
  const int steps = nx + kLag * (Rows - 1);
  const int full_begin = kLag * (Rows - 1);  // from here every row has a cell ...
  const int full_end = nx;                   // ... up to here
  const auto partial_step = [&](int t) {
    for (int k = 0; k < Rows; ++k) {
      const int i = t - kLag * k;
      if (i >= 0 && i < nx) update(t, k);
    }
  };
  int t = 0;
  for (; t < std::min(full_begin, steps); ++t) partial_step(t);
  for (; t < full_end; ++t) {
#pragma GCC unroll 8
    for (int k = 0; k < Rows; ++k) update(t, k);
  }
  for (; t < steps; ++t) partial_step(t);
}

}  // namespace

template <int Dim>
template <bool from_zero>
void MultigridPreconditioner<Dim>::forward_gauss_seidel(const Level& level,
                                                        const Eigen::VectorXd& b,
                                                        Eigen::VectorXd& x) {
  const int p = level.padding;
  const int nx = level.cells[0];
  const int rows = level.cell_count / nx;
  SweepOperator<Dim> a{};
  for (int d = 0; d < Dim; ++d) {
    a.coupling[d] = level.coupling[d].data();
    a.stride[d] = level.stride[d];
  }
  a.inverse_diagonal = level.inverse_diagonal.data();
  int row = 0;
  for (; row + kBlockRows <= rows; row += kBlockRows) {
    sweep_rows<Dim, true, from_zero, kBlockRows>(a, b.data(), x.data(), p + row * nx, nx);
  }
  for (; row < rows; ++row) {
    sweep_rows<Dim, true, from_zero, 1>(a, b.data(), x.data(), p + row * nx, nx);
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::backward_gauss_seidel(const Level& level,
                                                         const Eigen::VectorXd& b,
                                                         Eigen::VectorXd& x) {
  const int p = level.padding;
  const int nx = level.cells[0];
  const int rows = level.cell_count / nx;
  SweepOperator<Dim> a{};
  for (int d = 0; d < Dim; ++d) {
    a.coupling[d] = level.coupling[d].data();
    a.stride[d] = level.stride[d];
  }
  a.inverse_diagonal = level.inverse_diagonal.data();
  int row = rows - 1;
  for (; row + 1 >= kBlockRows; row -= kBlockRows) {
    sweep_rows<Dim, false, false, kBlockRows>(a, b.data(), x.data(), p + row * nx, nx);
  }
  for (; row >= 0; --row) sweep_rows<Dim, false, false, 1>(a, b.data(), x.data(), p + row * nx, nx);
}

namespace {

// r_i = b_c - (A x)_c for the nx cells c = first + i of a row (pointers at
// the row's first cell; the couplings' arrays at cell 0), the operations of
// multiply(). Apart so that the row loop vectorises.
template <int Dim>
inline void row_residual(const double* __restrict diagonal,
                         const std::array<const double*, Dim>& coupling,
                         const std::array<int, Dim>& stride, int first, const double* __restrict b,
                         const double* __restrict x, int nx, double* __restrict r) {
  std::array<const double*, Dim> t{};
  for (int d = 0; d < Dim; ++d) t[d] = coupling[d] + first;
  for (int i = 0; i < nx; ++i) {
    double product = diagonal[i] * x[i];
    for (int d = 0; d < Dim; ++d) {
      const int s = stride[d];
      product -= t[d][i] * x[i + s] + t[d][i - s] * x[i - s];
    }
    r[i] = b[i] - product;
  }
}

}  // namespace

// The residual b - A x restricted to the coarse level (the sum over each
// aggregate) in one pass, row by row along x: a row's residuals (the same
// operations as multiply() and a subtraction), then added to the coarse row
// its cells aggregate into, in cell order as a cell-by-cell sum would.
template <int Dim>
void MultigridPreconditioner<Dim>::restrict_residual(Level& fine, const Eigen::VectorXd& b,
                                                     const Eigen::VectorXd& x, Level& coarse) {
  const int pf = fine.padding;
  const int n = fine.cell_count;
  const int nx = fine.cells[0];
  const int* aggregate = fine.aggregate.data();
  const double* diagonal = fine.diagonal.data() + pf;
  const double* rhs = b.data() + pf;
  const double* v = x.data() + pf;
  std::array<const double*, Dim> t{};
  std::array<int, Dim> stride{};
  for (int d = 0; d < Dim; ++d) {
    t[d] = fine.coupling[d].data() + pf;
    stride[d] = fine.stride[d];
  }
  double* r = fine.row.data();
  coarse.right_hand_side.setZero();
  double* coarse_rhs = coarse.right_hand_side.data() + coarse.padding;
  for (int first = 0; first < n; first += nx) {
    row_residual<Dim>(diagonal + first, t, stride, first, rhs + first, v + first, nx, r);
    double* target = coarse_rhs + aggregate[first];
    if (fine.coarsened[0]) {
      for (int k = 0; k < nx / 2; ++k) target[k] = target[k] + r[2 * k] + r[2 * k + 1];
      if (nx % 2 != 0) target[nx / 2] += r[nx - 1];
    } else {
      for (int i = 0; i < nx; ++i) target[i] += r[i];
    }
  }
}

// x += scale P x_coarse: each cell takes its aggregate's correction.
template <int Dim>
void MultigridPreconditioner<Dim>::prolong(const Level& fine, const Level& coarse, double scale,
                                           Eigen::VectorXd& x) {
  const int n = fine.cell_count;
  const int nx = fine.cells[0];
  const int* aggregate = fine.aggregate.data();
  double* v = x.data() + fine.padding;
  const double* correction = coarse.solution.data() + coarse.padding;
  for (int first = 0; first < n; first += nx) {
    const double* source = correction + aggregate[first];
    double* row = v + first;
    if (fine.coarsened[0]) {
      for (int k = 0; k < nx / 2; ++k) {
        row[2 * k] += scale * source[k];
        row[2 * k + 1] += scale * source[k];
      }
      if (nx % 2 != 0) row[nx - 1] += scale * source[nx / 2];
    } else {
      for (int i = 0; i < nx; ++i) row[i] += scale * source[i];
    }
  }
}

// Solves level `level` approximately for b from x = 0: smoothing, coarse
// correction and smoothing, `cycle` times. The coarse levels keep their b
// and x in right_hand_side and solution; the finest takes the caller's.
template <int Dim>
void MultigridPreconditioner<Dim>::cycle(int level, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  Level& fine = levels_[static_cast<std::size_t>(level)];
  const int pf = fine.padding;
  const int n = fine.cell_count;
  if (level + 1 == level_count()) {
    coarsest_vector_ = b.segment(pf, n);
    coarsest_factor_.solveInPlace(coarsest_vector_);
    x.segment(pf, n) = coarsest_vector_;
    return;
  }
  Level& coarse = levels_[static_cast<std::size_t>(level) + 1];
  for (int visit = 0; visit < options_.cycle; ++visit) {
    for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep) {
      // x starts at 0 (the first sweep writes every cell).
      if (visit == 0 && sweep == 0) {
        forward_gauss_seidel<true>(fine, b, x);
      } else {
        forward_gauss_seidel<false>(fine, b, x);
      }
    }
    restrict_residual(fine, b, x, coarse);
    cycle(level + 1, coarse.right_hand_side, coarse.solution);
    prolong(fine, coarse, options_.correction_scale, x);
    for (int sweep = 0; sweep < options_.smoothing_sweeps; ++sweep) {
      backward_gauss_seidel(fine, b, x);
    }
  }
}

template <int Dim>
void MultigridPreconditioner<Dim>::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  // The sweeps read the padding as the zero values beyond the box.
  const int p = padding();
  z.head(p).setZero();
  z.tail(p).setZero();
  cycle(0, r, z);
}

template class MultigridPreconditioner<1>;
template class MultigridPreconditioner<2>;
template class MultigridPreconditioner<3>;

}  // namespace ice

#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace ice {

struct MultigridOptions {
  // Gauss-Seidel sweeps before (forward) and after (backward) each coarse
  // correction; equal counts keep the cycle symmetric.
  int smoothing_sweeps = 2;
  // Coarse-grid visits per level: 1 V-cycle, 2 W-cycle.
  int cycle = 1;
  // Along a coarsened direction the piecewise-constant Galerkin operator
  // couples aggregates twice as strongly as the operator rediscretised on
  // the coarse grid (the sum over two faces per aggregate face in place of
  // their series coupling); those coarse couplings are multiplied by this
  // factor (1 = pure Galerkin).
  double coupling_scale = 0.5;
  // The coarse correction is multiplied by this factor (Braess's
  // over-correction; 1 = none).
  double correction_scale = 1.0;
  // Coarsening stops once a level has at most this many cells; that level
  // is solved by a dense Cholesky factorisation.
  int coarsest_cells = 64;
};

// Cell-centred geometric multigrid for the symmetric positive definite
// pressure operator of the ICE step on a box of cells (x fastest):
//
//   (A x)_c = D_c x_c - sum_d ( T_d,c x_{c + s_d} + T_d,c-s_d x_{c - s_d} ),
//
// D the diagonal, T_d,c >= 0 the coupling of cell c with its upper
// neighbour along d (stride s_d; 0 for the last cell of a row).
//
// Levels: aggregates of 2 cells along each coarsened direction (the last
// aggregate of an odd row holds one), piecewise-constant prolongation P,
// restriction P^T and coarse operators P^T A P (Galerkin; robust to the
// 1000:1 density jumps at a water-air interface), with the couplings along
// coarsened directions scaled by MultigridOptions::coupling_scale. A
// direction is coarsened while its (level) spacing is below twice the
// smallest one, so stretched cells are first coarsened along their short
// sides (semi-coarsening) until the level is near isotropic. One application is a symmetric V-cycle
// (forward Gauss-Seidel down, backward Gauss-Seidel up, the coarsest level
// solved exactly), so it is a valid conjugate-gradient preconditioner.
//
// The hierarchy's structure is built once; set_fine_operator's values and
// update() (O(N)) are per matrix. Vectors are held in the padded layout:
// padding() zeros, the cell_count() values, padding() zeros. Nothing is
// allocated after construction.
template <int Dim>
class MultigridPreconditioner {
 public:
  using CellCounts = std::array<int, Dim>;
  using Spacing = std::array<double, Dim>;

  // Throws std::invalid_argument for a cell count below one, a non-positive
  // spacing or bad options.
  MultigridPreconditioner(const CellCounts& cells, const Spacing& spacing,
                          MultigridOptions options = {});

  int cell_count() const { return levels_.front().cell_count; }
  int padding() const { return levels_.front().padding; }
  int padded_size() const { return cell_count() + 2 * padding(); }
  int level_count() const { return static_cast<int>(levels_.size()); }
  const CellCounts& level_cells(int level) const { return levels_[level].cells; }

  // The finest operator: diagonal(c) = A_cc, coupling(d, c) = -A(c, c + s_d)
  // for the upper neighbour along d; the coupling of the last cell of a row
  // must stay 0. Cells are unpadded flat indices.
  double& diagonal(int cell) { return levels_.front().diagonal[padding() + cell]; }
  double& coupling(int direction, int cell) {
    return levels_.front().coupling[direction][padding() + cell];
  }
  double diagonal(int cell) const { return levels_.front().diagonal[padding() + cell]; }
  double coupling(int direction, int cell) const {
    return levels_.front().coupling[direction][padding() + cell];
  }

  // Builds the coarse operators and factorises the coarsest one from the
  // finest operator. Throws cosim::NumericalError when the coarsest operator
  // is not positive definite.
  void update();

  // The operator of `level` (0 finest) as last built by update(), in
  // unpadded cell indices; for inspection (allocates).
  Eigen::SparseMatrix<double> level_operator(int level) const;

  // y = A x on the finest level (padded vectors).
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  // s = z + beta s, then y = A s (the conjugate-gradient direction and its
  // product), in one pass; the same values as the two steps.
  void update_and_multiply(const Eigen::VectorXd& z, double beta, Eigen::VectorXd& s,
                           Eigen::VectorXd& y) const;

  // z = M^{-1} r, one cycle from z = 0 (padded vectors).
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);

 private:
  struct Level {
    CellCounts cells{};
    CellCounts stride{};
    int cell_count = 0;
    int padding = 0;
    Eigen::VectorXd diagonal;
    Eigen::VectorXd inverse_diagonal;
    // Row sums of the operator (kappa V / dt plus the fixed-pressure ghost
    // couplings): kept apart so that the coarse diagonals do not come from
    // cancelling the large couplings inside an aggregate.
    Eigen::VectorXd surplus;
    std::array<Eigen::VectorXd, Dim> coupling;
    // b and x of the coarse levels (the finest uses the caller's vectors).
    Eigen::VectorXd solution;
    Eigen::VectorXd right_hand_side;
    // One row of residuals (restrict_residual's scratch).
    Eigen::VectorXd row;
    // The coarse cell of each cell (unpadded indices) and the directions
    // coarsened to the next level; empty and unused on the coarsest.
    std::vector<int> aggregate;
    std::array<bool, Dim> coarsened{};
  };

  static Level make_level(const CellCounts& cells);
  static void multiply(const Level& level, const Eigen::VectorXd& x, Eigen::VectorXd& y);
  template <bool from_zero>
  static void forward_gauss_seidel(const Level& level, const Eigen::VectorXd& b,
                                   Eigen::VectorXd& x);
  static void backward_gauss_seidel(const Level& level, const Eigen::VectorXd& b,
                                    Eigen::VectorXd& x);
  static void restrict_residual(Level& fine, const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                                Level& coarse);
  static void prolong(const Level& fine, const Level& coarse, double scale, Eigen::VectorXd& x);
  static void set_diagonal_from_couplings(Level& level);
  static void set_inverse_diagonal(Level& level);
  void build_coarse_operator(int level);
  void cycle(int level, const Eigen::VectorXd& b, Eigen::VectorXd& x);

  MultigridOptions options_;
  std::vector<Level> levels_;
  Eigen::MatrixXd coarsest_matrix_;
  Eigen::VectorXd coarsest_vector_;
  Eigen::LLT<Eigen::MatrixXd> coarsest_factor_;
};

extern template class MultigridPreconditioner<1>;
extern template class MultigridPreconditioner<2>;
extern template class MultigridPreconditioner<3>;

}  // namespace ice

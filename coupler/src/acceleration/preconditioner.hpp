#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "state_io.hpp"

namespace cosim::acceleration {

// Per-block weights w_b of IQN-ILS's least squares problem: every entry of
// block b of the residual r and of the columns of V is multiplied by w_b, so
// that a pressure in Pa and a velocity in m/s both count (as preCICE's
// preconditioners). W is used unweighted: scaling W and unscaling W c, as
// preCICE does, is the identity.
//   none:          w_b = 1.
//   value:         w_b = 1 / ||x_b|| of the window's first iterate (1 if that
//                  norm is zero).
//   residual_sum:  w_b = 1 / sum_k ||r_b^k|| / ||r^k|| over the window's
//                  iterations so far (preCICE's residual-sum preconditioner).
//                  An iteration with r = 0 adds nothing; a block whose sum is
//                  still zero keeps its weight (1 at first).
// After `freeze_after` converged windows (0: never) the weights no longer
// change.
class PreconditionerWeights {
 public:
  PreconditionerWeights(Preconditioner kind, std::vector<Block> blocks, std::size_t freeze_after);

  // One iteration of the window: the iterate x and its residual r.
  void update(const Eigen::Ref<const Eigen::VectorXd>& x,
              const Eigen::Ref<const Eigen::VectorXd>& r);
  // Starts the next window's sums.
  void window_converged();

  bool frozen() const { return freeze_after_ > 0 && converged_windows_ >= freeze_after_; }
  const std::vector<double>& block_weights() const { return weights_; }

  // Multiplies the rows of each block by its weight.
  void apply(Eigen::Ref<Eigen::MatrixXd> rows) const;

  void write(detail::StateWriter& writer) const;
  void read(detail::StateReader& reader);

 private:
  Preconditioner kind_;
  std::vector<Block> blocks_;
  std::size_t freeze_after_;
  std::vector<double> weights_;
  std::vector<double> residual_sums_;
  std::vector<double> first_residual_norms_;
  std::size_t iterations_in_window_ = 0;
  std::size_t converged_windows_ = 0;
};

}  // namespace cosim::acceleration

#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "multi_vector_jacobian.hpp"
#include "preconditioner.hpp"

namespace cosim::acceleration {

// Interface quasi-Newton with an approximation for the inverse of the Jacobian
// from a least-squares model (IQN-ILS, Degroote et al. 2009). With the
// residual r^k = h^k - x^k, h^k = H(x^k), each pair of successive iterations
// gives a column of
//   V = [r^k - r^{k-1}, ...],   W = [h^k - h^{k-1}, ...]   (newest first),
// and
//   c = argmin ||P (V c + r^k)||,   x^{k+1} = h^k + W c,
// where P holds the preconditioner's block weights. The least squares problem
// is solved with the filtered QR factorisation of P V (qr_filter.hpp), whose
// dropped columns leave V and W for good. Without columns (none yet, or all
// filtered out), x^{k+1} = x^k + omega r^k.
//
// Columns come from the iterations of the current window and, when a window
// has converged (its last pair included), those of the last `reuse_windows`
// converged windows are kept for the next ones (preCICE's reused time
// windows). At most `max_columns` are kept, the oldest
// dropped first.
//
// IQN-IMVJ (Method::iqn_imvj; Lindner et al. 2015) carries the history as a
// Jacobian J instead (multi_vector_jacobian.hpp): a window's columns are its
// own, each converged window updates J with them, and
//   x^{k+1} = h^k + W c - J (r^k + V c),
// which is x^{k+1} = h^k - J_n r^k with J_n = J + (W - J V) Z. Without
// columns, x^{k+1} = h^k - J r^k, or the relaxation while J is still zero.
class IqnIls final : public Accelerator {
 public:
  IqnIls(const AccelerationSpec& spec, std::vector<Block> blocks);

  void accelerate(std::span<const double> x, std::span<const double> h,
                  std::span<double> next) override;
  void window_converged(std::span<const double> x, std::span<const double> h) override;
  AcceleratorState state() const override;
  void restore(const AcceleratorState& s) override;
  std::size_t columns() const override { return columns_.size(); }
  // IQN-IMVJ: the windows whose updates J holds.
  std::size_t jacobian_updates() const { return jacobian_.updates(); }

  const PreconditionerWeights& preconditioner() const { return weights_; }

 private:
  struct Column {
    Eigen::VectorXd residual_difference;  // of V
    Eigen::VectorXd output_difference;    // of W
    std::size_t window;                   // the window whose iterations gave it
  };

  // Adds the column from the window's previous pair to (r, h), and makes
  // (r, h) the previous pair.
  void add_pair(const Eigen::VectorXd& r, const Eigen::VectorXd& h);
  // c of min ||P (V c + r)||; drops the columns the filter leaves out.
  Eigen::VectorXd least_squares_coefficients(const Eigen::VectorXd& r);
  // IQN-IMVJ: the window's columns update J and leave.
  void move_columns_into_jacobian();

  Method method_;
  double relaxation_;
  std::size_t max_columns_;
  std::size_t reuse_windows_;
  Filter filter_;
  double filter_limit_;
  std::size_t size_;
  PreconditionerWeights weights_;
  std::deque<Column> columns_;  // newest first
  std::size_t window_ = 0;      // converged windows so far
  bool window_has_pair_ = false;
  Eigen::VectorXd previous_residual_;
  Eigen::VectorXd previous_output_;
  MultiVectorJacobian jacobian_;
};

}  // namespace cosim::acceleration

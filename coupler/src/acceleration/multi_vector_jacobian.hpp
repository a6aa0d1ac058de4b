#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>

#include "state_io.hpp"

namespace cosim::acceleration {

// The approximate inverse Jacobian of the residual-to-output map that IQN-IMVJ
// carries from window to window (Lindner, Mehl, Uekermann & Bungartz 2015):
// each converged window n, with its columns V_n, W_n, updates
//   J_n = J_{n-1} + (W_n - J_{n-1} V_n) Z_n,   Z_n = (P V_n)^+ P,
// so that J_n V_n = W_n while J_{n-1} still acts on the directions V_n does
// not span. J is never formed: it is kept as its updates A_m = W_m - J_{m-1}
// V_m and Z_m^T, and J y = sum_m A_m (Z_m y), at O(size x columns) per
// product. The last `windows` updates are kept, the oldest dropped first
// (J_0 = 0), which bounds the memory as IQN-ILS's reused windows do.
class MultiVectorJacobian {
 public:
  MultiVectorJacobian(std::size_t windows, std::size_t size);

  bool empty() const { return updates_.empty(); }
  std::size_t updates() const { return updates_.size(); }

  Eigen::VectorXd times(const Eigen::VectorXd& y) const;

  // A converged window's columns (V, W) and Z^T = P Q R^-T from the QR
  // factorisation P V = Q R of the same columns.
  void update(const Eigen::MatrixXd& v, const Eigen::MatrixXd& w, Eigen::MatrixXd z_transposed);

  void write(detail::StateWriter& writer) const;
  void read(detail::StateReader& reader);

 private:
  struct Update {
    Eigen::MatrixXd a;             // W_m - J_{m-1} V_m
    Eigen::MatrixXd z_transposed;  // Z_m^T
  };

  std::size_t windows_;
  std::size_t size_;
  std::deque<Update> updates_;  // newest first
};

}  // namespace cosim::acceleration

#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

#include "accelerator.hpp"

namespace cosim::acceleration {

// A thin QR decomposition V_kept = Q R of the columns of V that carry new
// information, newest (first) column first (Haelterman et al. 2016):
//   qr2  a column is dropped when Gram-Schmidt against the columns kept
//        before it leaves less than `limit` of its norm;
//   qr1  columns whose |R_ii| < limit ||R||_F are dropped, and the rest
//        decomposed again, until none is;
//   none only columns that are exactly dependent are dropped.
// Modified Gram-Schmidt, each column orthogonalised twice.
struct FilteredQR {
  std::vector<std::size_t> kept;  // indices into V's columns, in order
  Eigen::MatrixXd q;              // rows x kept
  Eigen::MatrixXd r;              // kept x kept, upper triangular
};

FilteredQR filtered_qr(const Eigen::MatrixXd& v, Filter filter, double limit);

}  // namespace cosim::acceleration

#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "acceleration/accelerator.hpp"

namespace cosim::acceleration {

// The thin QR factorisation V_kept = Q R of the columns of V (newest first)
// that the filter keeps, for IQN-ILS's least squares problem min ||V c + r||.
struct FilteredQr {
  Eigen::MatrixXd q;                 // rows x kept, orthonormal columns
  Eigen::MatrixXd r;                 // kept x kept, upper triangular
  std::vector<std::size_t> kept;     // V's column of each column of Q, ascending
  std::vector<std::size_t> dropped;  // V's columns left out, ascending
};

// Q and R are built column by column, newest first, by classical Gram-Schmidt
// with one reorthogonalisation (CGS2), which keeps Q orthonormal to rounding
// for numerically independent columns (Giraud, Langou & Rozložník 2005). Whatever the filter, a
// column is left out when it adds no direction at working precision: it is zero, its part
// orthogonal to the kept columns is below 64 eps of its norm, or the kept
// columns already span all rows.
//   none: nothing else is left out.
//   qr1:  the newest column i with |R_ii| < limit ||R||_F is left out and the
//         remaining columns refactored, until no column is below the limit.
//         An older column is left out only if every newer one passes, but a
//         small newest difference can go as well.
//   qr2:  (Haelterman et al. 2016) column i is left out when, orthogonalised
//         against the newer columns kept, ||v_i_orth|| < limit ||v_i||. The
//         newest column is always kept (unless zero): newer information has
//         priority over older.
FilteredQr filtered_qr(const Eigen::MatrixXd& v, Filter filter, double limit);

}  // namespace cosim::acceleration

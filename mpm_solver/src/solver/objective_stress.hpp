#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "mpm/core/tensor.hpp"

namespace mpm::detail {

// Rotation of a step for the Jaumann rate (Zheng et al., eq. 5) in its
// incrementally objective form: the Cayley transform of the spin increment
// W dt, R = (I - W dt / 2)^-1 (I + W dt / 2), an exact rotation.
inline Tensor jaumann_rotation(const Tensor& spin_increment) {
  const Tensor half = 0.5 * spin_increment;
  return (Tensor::Identity() - half).inverse() * (Tensor::Identity() + half);
}

// Rotation R of the polar decomposition F = R U (Tran et al., MPMICE,
// eq. 11 writes F = V R; the rotation is the same).
template <int Dim>
Tensor polar_rotation(const Mat<Dim>& F) {
  if constexpr (Dim == 2) {
    const double angle = std::atan2(F(1, 0) - F(0, 1), F(0, 0) + F(1, 1));
    Tensor R = Tensor::Identity();
    R(0, 0) = std::cos(angle);
    R(0, 1) = -std::sin(angle);
    R(1, 0) = std::sin(angle);
    R(1, 1) = std::cos(angle);
    return R;
  } else {
    Eigen::JacobiSVD<Tensor> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Tensor R = svd.matrixU() * svd.matrixV().transpose();
    if (R.determinant() < 0.0) {
      Tensor U = svd.matrixU();
      U.col(2) *= -1.0;
      R = U * svd.matrixV().transpose();
    }
    return R;
  }
}

}  // namespace mpm::detail

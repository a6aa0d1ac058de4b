#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "mpm/core/tensor.hpp"

namespace mpm::detail {

// Rotation of a step for the Jaumann rate (Zheng et al., eq. 5) in its
// incrementally objective form: the Cayley transform of the spin increment
// W dt, R = (I - W dt / 2)^-1 (I + W dt / 2), an exact rotation. In closed
// form with A = W dt / 2 = skew(a): R = I + 2 (A + A^2) / (1 + a . a).
inline Tensor jaumann_rotation(const Tensor& spin_increment) {
  const Tensor half = 0.25 * (spin_increment - spin_increment.transpose());
  const double a_squared =
      half(2, 1) * half(2, 1) + half(0, 2) * half(0, 2) + half(1, 0) * half(1, 0);
  return Tensor::Identity() + (2.0 / (1.0 + a_squared)) * (half + half * half);
}

// sigma <- R sigma R^T with R = jaumann_rotation of the spin increment
// W dt. In 2D the spin turns the x-y plane only: with a = W_yx dt / 2,
// R = [[1 - a^2, -2a], [2a, 1 - a^2]] / (1 + a^2) on that block.
template <int Dim>
void rotate_by_jaumann(const Mat<Dim>& spin_increment, Tensor& stress) {
  if constexpr (Dim == 2) {
    const double a = 0.25 * (spin_increment(1, 0) - spin_increment(0, 1));
    const double scale = 1.0 / (1.0 + a * a);
    Mat<2> R;
    R << (1.0 - a * a) * scale, -2.0 * a * scale, 2.0 * a * scale, (1.0 - a * a) * scale;
    const Mat<2> in_plane = R * stress.topLeftCorner<2, 2>() * R.transpose();
    const Vec<2> out_of_plane = R * stress.topRightCorner<2, 1>();
    stress.topLeftCorner<2, 2>() = in_plane;
    stress.topRightCorner<2, 1>() = out_of_plane;
    stress.bottomLeftCorner<1, 2>() = out_of_plane.transpose();
  } else {
    const Tensor R = jaumann_rotation(spin_increment);
    stress = R * stress * R.transpose();
  }
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

#pragma once

#include <Eigen/Dense>

// Small fixed-size tensors of the MPM solver. Vectors and gradients live in
// the problem's dimension; stresses are always 3 x 3 (plane strain keeps
// sigma_zz), so constitutive models are written once for 2D and 3D.
namespace mpm {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;

using Vec3d = Eigen::Vector3d;
using Tensor = Eigen::Matrix3d;

// A Dim x Dim tensor embedded in 3 x 3; the out-of-plane block is `diagonal`
// on the diagonal (1 for deformation gradients, 0 for rates) in plane strain.
template <int Dim>
Tensor embed(const Mat<Dim>& m, double diagonal) {
  if constexpr (Dim == 3) {
    return m;
  } else {
    Tensor t = Tensor::Identity() * diagonal;
    t.template topLeftCorner<Dim, Dim>() = m;
    return t;
  }
}

// Symmetric part and skew part of a tensor.
inline Tensor sym(const Tensor& t) {
  return 0.5 * (t + t.transpose());
}
inline Tensor skew(const Tensor& t) {
  return 0.5 * (t - t.transpose());
}

}  // namespace mpm

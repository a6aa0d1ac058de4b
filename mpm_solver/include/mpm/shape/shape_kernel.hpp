#pragma once

#include <concepts>
#include <string_view>

// Shape functions of the background grid. Every shape is a tensor product of
// a one-dimensional kernel; a kernel is a type with
//
//   static constexpr int support;         // grid values a point touches per direction
//   static int dofs(int cells);           // grid values per direction for `cells` cells
//   static double dof_coordinate(int i, int cells);  // position of value i, in cells from the
//   origin
//   // Weights N[0..support) and derivatives dN (per unit of the grid
//   // coordinate; divide by the spacing for d/dx) of the values
//   // first, first+1, ... at grid coordinate xi = (x - origin) / h, for a
//   // point whose domain half-length is `half_length` (in cells; only GIMP
//   // uses it). Returns `first`. Always 0 <= first and
//   // first + support <= dofs(cells) for 0 <= xi <= cells; values outside the
//   // grid get no weight and the weights still sum to 1.
//   static int evaluate(double xi, double half_length, int cells, double* N, double* dN);
//
// Kernels clamp xi to [0, cells] (a point that left the grid is weighed as
// if it sat on the face), so the solver must remove or stop such points.
// The kernels are LinearKernel, GimpKernel and QuadraticBsplineKernel
// (mpm/shape/*_kernel.hpp); Stencil (stencil.hpp) forms their tensor
// products and with_kernel (shape_dispatch.hpp) picks one for a ShapeKind.
//
// The grid values ("nodes") are the grid nodes for the linear and GIMP
// kernels and the control points of the open-knot B-spline (at the Greville
// abscissae: both faces and every cell centre) for the quadratic B-spline.
// The first and last value of every kernel sit on the domain faces, so
// boundary conditions set them.
namespace mpm {

enum class ShapeKind {
  linear,             // C0 hat functions
  gimp,               // Zheng et al., eq. 11 (uGIMP: undeformed particle domain)
  quadratic_bspline,  // Pan et al. 2021, App. A (open knot vector, Cox-de Boor)
};

std::string_view to_string(ShapeKind kind);

template <class K>
concept ShapeKernel = requires(double xi, double half_length, int cells, double* N, double* dN) {
  { K::support } -> std::convertible_to<int>;
  { K::dofs(cells) } -> std::same_as<int>;
  { K::dof_coordinate(cells, cells) } -> std::same_as<double>;
  { K::evaluate(xi, half_length, cells, N, dN) } -> std::same_as<int>;
};

}  // namespace mpm

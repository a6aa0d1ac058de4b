#pragma once

#include <string_view>

// Shape functions of the background grid. Every shape is a tensor product of
// a one-dimensional kernel; a kernel is a type with
//
//   static constexpr int support;         // grid values a point touches per direction
//   static int dofs(int cells);           // grid values per direction for `cells` cells
//   static double dof_coordinate(int i, int cells);  // position of value i, in cells from the origin
//   // Weights N[0..support) and derivatives dN (per unit of the grid
//   // coordinate; divide by the spacing for d/dx) of the values
//   // first, first+1, ... at grid coordinate xi = (x - origin) / h, for a
//   // point whose domain half-length is `half_length` (in cells; only GIMP
//   // uses it). Returns `first`. Always 0 <= first and
//   // first + support <= dofs(cells) for 0 <= xi <= cells; values outside the
//   // grid get no weight and the weights still sum to 1.
//   static int evaluate(double xi, double half_length, int cells, double* N, double* dN);
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

}  // namespace mpm

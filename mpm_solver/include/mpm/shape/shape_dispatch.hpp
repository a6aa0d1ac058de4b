#pragma once

#include <utility>

#include "mpm/shape/gimp_kernel.hpp"
#include "mpm/shape/linear_kernel.hpp"
#include "mpm/shape/quadratic_bspline_kernel.hpp"
#include "mpm/shape/shape_kernel.hpp"

namespace mpm {

// Calls f(Kernel{}) with the kernel type of `kind`, so a loop over points is
// written once as a template on the kernel and dispatched once per loop:
//
//   with_kernel<Dim>(kind, [&](auto kernel) {
//     using Kernel = decltype(kernel);
//     for (...) { Stencil<Dim, Kernel> s; s.evaluate(...); ... }
//   });
//
// Every branch must return the same type.
template <int Dim, class F>
decltype(auto) with_kernel(ShapeKind kind, F&& f) {
  static_assert(Dim >= 1 && Dim <= 3);
  switch (kind) {
    case ShapeKind::gimp:
      return std::forward<F>(f)(GimpKernel{});
    case ShapeKind::quadratic_bspline:
      return std::forward<F>(f)(QuadraticBsplineKernel{});
    case ShapeKind::linear:
      break;
  }
  return std::forward<F>(f)(LinearKernel{});
}

}  // namespace mpm

#include "mpm/shape/shape_kernel.hpp"

namespace mpm {

std::string_view to_string(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::linear:
      return "linear";
    case ShapeKind::gimp:
      return "gimp";
    case ShapeKind::quadratic_bspline:
      return "quadratic_bspline";
  }
  return "unknown";
}

}  // namespace mpm

#include "mapping/constraint.hpp"

#include <string>

#include "cosim/error.hpp"

namespace cosim::mapping {

const char* to_string(Constraint constraint) {
  return constraint == Constraint::conservative ? "conservative" : "consistent";
}

const char* to_string(Kernel kernel) {
  return kernel == Kernel::linear ? "linear" : "quadratic_bspline";
}

Constraint constraint_from_string(std::string_view name) {
  if (name == "conservative") return Constraint::conservative;
  if (name == "consistent") return Constraint::consistent;
  throw InputError("unknown mapping constraint '" + std::string(name) +
                   "' (expected 'conservative' or 'consistent')");
}

Kernel kernel_from_string(std::string_view name) {
  if (name == "linear") return Kernel::linear;
  if (name == "quadratic_bspline") return Kernel::quadratic_bspline;
  throw InputError("unknown mapping kernel '" + std::string(name) +
                   "' (expected 'linear' or 'quadratic_bspline')");
}

Constraint constraint_for(Quantity quantity) {
  return quantity == Quantity::extensive ? Constraint::conservative : Constraint::consistent;
}

}  // namespace cosim::mapping

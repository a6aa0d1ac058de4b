#pragma once

#include <cstdint>
#include <string_view>

#include "cosim/field.hpp"

// What a mapping operator preserves, and the kernel it uses between clouds
// and grids (architecture.md §5).
namespace cosim::mapping {

enum class Constraint : std::uint8_t {
  conservative,  // extensive values: Σ target = Σ source; columns of the weights sum to 1
  consistent,    // intensive values: weighted averages; rows of the weights sum to 1
};

// Partition-of-unity kernels for point/cell clouds ↔ uniform grids, centred
// on the grid's value locations (cell centres or nodes).
enum class Kernel : std::uint8_t {
  linear,             // tent, support ±1 spacing
  quadratic_bspline,  // uniform quadratic B-spline, support ±1.5 spacings (Pan et al. 2021, App. A)
};

struct Options {
  Kernel kernel = Kernel::linear;
};

const char* to_string(Constraint constraint);
const char* to_string(Kernel kernel);
// Both throw InputError listing the accepted names.
Constraint constraint_from_string(std::string_view name);
Kernel kernel_from_string(std::string_view name);

// Extensive quantities map conservatively, intensive ones consistently.
Constraint constraint_for(Quantity quantity);

}  // namespace cosim::mapping

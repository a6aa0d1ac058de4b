#pragma once

#include <memory>
#include <vector>

#include "bench/analytic_solution.hpp"

namespace cosim::bench {

// The solutions the bench knows by name (analytic_solution.hpp).
std::vector<std::unique_ptr<AnalyticSolution>> builtin_solutions();

}  // namespace cosim::bench

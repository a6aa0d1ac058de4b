#pragma once

#include <functional>
#include <span>

namespace mpm::coupling {

// On a rank of a decomposed MPM (issue 27): adds the other ranks' values to
// this rank's, in place, so that every rank holds the sums over all points
// (collective). Empty on one process.
using SumOverRanks = std::function<void(std::span<double>)>;

}  // namespace mpm::coupling

#pragma once

#include <functional>
#include <span>
#include <vector>

// On a rank of a decomposed MPM (issue 27), how the coupling joins what its
// points give to the other ranks' (each collective; empty on one process).
namespace mpm::coupling {

// Adds the other ranks' values to this rank's, in place, so that every
// rank holds the sums over all points.
using SumOverRanks = std::function<void(std::span<double>)>;
// The largest of every rank's values, element by element, in place.
using MaxOverRanks = std::function<void(std::span<double>)>;
// Every rank's values one after the other, in rank order.
using GatherOverRanks = std::function<std::vector<double>(std::span<const double>)>;

}  // namespace mpm::coupling

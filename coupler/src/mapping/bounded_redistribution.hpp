#pragma once

#include <span>

#include "cosim/mesh.hpp"

namespace cosim::mapping {

// Brings a bounded fraction field (e.g. solid volume fraction after a
// conservative transfer) back into [lo, hi] without changing Σ fraction·V,
// V being the mesh's control volumes. Plain clipping would lose the excess.
//
// Each element above `hi` is set to `hi` and its excess volume is spread over
// its neighbours in breadth-first layers (nearest layer first), shared within
// a layer in proportion to the free capacity (hi − φ)·V; a full layer passes
// the rest to the next. Elements below `lo` draw their deficit the same way
// from the neighbours' surplus (φ − lo)·V. Neighbours are face neighbours on
// grids, left/right cells on lines, and on clouds the elements in the same and
// adjacent bins of a uniform binning whose bin size is the typical element size
// ((mean volume)^(1/dim), enlarged for sparse clouds). When a breadth-first
// search runs out of connected elements the rest goes to all remaining ones.
//
// The result depends on the element order when excess regions touch.
// Throws InputError for size mismatch, lo > hi or non-finite values, and
// NumericalError when the total cannot fit (Σ hi·V < Σ φ·V or Σ lo·V > Σ φ·V).
void redistribute_to_bounds(const Mesh& mesh, std::span<double> fraction, double lo, double hi);

}  // namespace cosim::mapping

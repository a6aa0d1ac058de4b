#pragma once

#include "mpm/core/tensor.hpp"

namespace mpm {

// An axis-aligned box, half-open: it holds lower <= x < upper, so boxes that
// share a face never both claim a point on it. Also the bounding box of the
// other regions.
template <int Dim>
struct Box {
  Vec<Dim> lower = Vec<Dim>::Zero();
  Vec<Dim> upper = Vec<Dim>::Zero();

  bool contains(const Vec<Dim>& x) const {
    return (x.array() >= lower.array()).all() && (x.array() < upper.array()).all();
  }
  const Box& bounding_box() const { return *this; }
  double volume() const { return (upper - lower).cwiseMax(0.0).prod(); }
};

}  // namespace mpm

#include "mapping/bounded_redistribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "element_neighbours.hpp"

namespace cosim::mapping {
namespace {

constexpr std::size_t unvisited = std::numeric_limits<std::size_t>::max();

// Moves `amount` (a volume: Δφ·V) from element `origin` into the elements
// around it towards `bound`, breadth-first: each layer takes what it can, in
// proportion to its capacity |bound − φ|·V on the far side of the bound.
class Spreader {
 public:
  Spreader(const detail::ElementNeighbours& graph, std::span<double> phi,
           const std::vector<double>& volume)
      : graph_(graph), phi_(phi), volume_(volume), stamp_(phi.size(), unvisited) {}

  void spread(std::size_t origin, double amount, double bound, double direction) {
    std::vector<std::size_t> layer{origin};
    stamp_[origin] = origin;
    std::vector<std::size_t> next;
    while (amount > 0.0) {
      next.clear();
      for (const std::size_t e : layer)
        for (std::size_t k = graph_.start[e]; k < graph_.start[e + 1]; ++k) {
          const std::size_t n = graph_.neighbour[k];
          if (stamp_[n] == origin) continue;
          stamp_[n] = origin;
          next.push_back(n);
        }
      if (next.empty()) {  // disconnected: the rest of the mesh is the next layer
        for (std::size_t n = 0; n < phi_.size(); ++n)
          if (stamp_[n] != origin) {
            stamp_[n] = origin;
            next.push_back(n);
          }
        if (next.empty()) return;  // only round-off can be left here
      }
      double capacity = 0.0;
      for (const std::size_t n : next) capacity += room(n, bound, direction);
      if (capacity >= amount) {
        const double share = amount / capacity;
        for (const std::size_t n : next)
          if (room(n, bound, direction) > 0.0)
            phi_[n] = limit(phi_[n] + share * (bound - phi_[n]), bound, direction);
        return;
      }
      for (const std::size_t n : next)
        if (room(n, bound, direction) > 0.0) phi_[n] = bound;
      amount -= capacity;
      layer.swap(next);
    }
  }

 private:
  double room(std::size_t n, double bound, double direction) const {
    return std::max(0.0, direction * (bound - phi_[n]) * volume_[n]);
  }
  static double limit(double value, double bound, double direction) {
    return direction > 0.0 ? std::min(value, bound) : std::max(value, bound);
  }

  const detail::ElementNeighbours& graph_;
  std::span<double> phi_;
  const std::vector<double>& volume_;
  std::vector<std::size_t> stamp_;
};

std::string volume_text(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

}  // namespace

void redistribute_to_bounds(const Mesh& mesh, std::span<double> fraction, double lo, double hi) {
  validate(mesh);
  const std::size_t n = mesh.size();
  if (fraction.size() != n)
    throw InputError("bounded redistribution on mesh '" + mesh.name +
                     "': " + std::to_string(fraction.size()) + " values for " + std::to_string(n) +
                     " elements");
  if (!(lo <= hi))
    throw InputError("bounded redistribution on mesh '" + mesh.name + "': bounds [" +
                     volume_text(lo) + ", " + volume_text(hi) + "] are not ordered");
  bool inside = true;
  for (std::size_t e = 0; e < n; ++e) {
    if (!std::isfinite(fraction[e]))
      throw NumericalError("bounded redistribution on mesh '" + mesh.name +
                           "': non-finite value at element " + std::to_string(e));
    inside = inside && fraction[e] >= lo && fraction[e] <= hi;
  }
  if (inside) return;

  std::vector<double> volume(n);
  double total = 0.0;
  double room_below_hi = 0.0;
  double floor_of_lo = 0.0;
  for (std::size_t e = 0; e < n; ++e) {
    volume[e] = mesh.control_volume(e);
    total += fraction[e] * volume[e];
    room_below_hi += hi * volume[e];
    floor_of_lo += lo * volume[e];
  }
  const double tolerance =
      1e-12 * std::max({std::abs(total), std::abs(room_below_hi), std::abs(floor_of_lo)});
  if (total > room_below_hi + tolerance || total < floor_of_lo - tolerance)
    throw NumericalError("bounded redistribution on mesh '" + mesh.name + "': the total " +
                         volume_text(total) + " cannot fit within [" + volume_text(lo) + ", " +
                         volume_text(hi) + "] (bounds allow " + volume_text(floor_of_lo) + " to " +
                         volume_text(room_below_hi) + ")");

  const detail::ElementNeighbours graph = detail::element_neighbours(mesh);
  Spreader spreader(graph, fraction, volume);
  for (std::size_t e = 0; e < n; ++e)
    if (fraction[e] > hi) {
      const double excess = (fraction[e] - hi) * volume[e];
      fraction[e] = hi;
      spreader.spread(e, excess, hi, 1.0);
    }
  for (std::size_t e = 0; e < n; ++e)
    if (fraction[e] < lo) {
      const double deficit = (lo - fraction[e]) * volume[e];
      fraction[e] = lo;
      spreader.spread(e, deficit, lo, -1.0);
    }
}

}  // namespace cosim::mapping

#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "mpm/particles/particles.hpp"

namespace mpm {

// One array of grid values as the partition moves it: `fields` blocks of
// the stored values (field-major, as Grid's arrays), `components` numbers
// per value.
struct GridArray {
  double* data = nullptr;
  int components = 1;
  int fields = 0;  // blocks of values: 0 for every velocity field, 1 for one (heat)
};

// Which planes of grid values (along the grid's last direction) one rank
// stores and which of those it owns, as half-open [first, end) plane
// indices of the whole grid.
struct PlaneRanges {
  int stored_first = 0, stored_end = 0;
  int owned_first = 0, owned_end = 0;
};

// What joins one rank's part of a decomposed MPM background grid to the
// others (issue 27). The grid is cut into slabs of whole cell rows along its
// last direction, at multiples of the particle-to-grid scatter's slabs, so
// that every grid value gets the same partial sums as on one process. A
// rank holds the points of its rows and owns the grid values whose position
// lies in them; the values its points touch beyond are ghosts. The solver
// stays free of MPI: mpm/parallel implements this over MPI ranks.
template <int Dim>
class GridPartition {
 public:
  virtual ~GridPartition() = default;

  // The cell rows [first, end) along the last direction this rank owns.
  virtual std::array<int, 2> owned_rows() const = 0;
  // Tells the partition, once, which planes this rank stores and owns and
  // the values per plane and field (collective).
  virtual void set_planes(const PlaneRanges& planes, std::size_t plane_size, int fields) = 0;
  // Adds the partial sums each rank scattered into its ghost values to the
  // owners' values (collective).
  virtual void accumulate(std::span<const GridArray> arrays) = 0;
  // Gives the ghost values their owners' values (collective).
  virtual void exchange(std::span<const GridArray> arrays) = 0;
  // The largest of every rank's `local` (collective; exact).
  virtual double max(double local) = 0;
  // Every rank's `values` summed, in place (collective).
  virtual void sum(std::span<double> values) = 0;
  // The largest of every rank's `values`, element by element, in place
  // (collective; exact).
  virtual void max(std::span<double> values) = 0;
  // Every rank's `values` one after the other, in rank order (collective).
  virtual std::vector<double> gather(std::span<const double> values) = 0;
  // Sends every point another rank owns there and takes in those sent here,
  // keeping the points in id order (collective).
  virtual void migrate(Particles<Dim>& particles) = 0;
};

}  // namespace mpm

#pragma once

#include <array>
#include <span>

namespace swe {

// What joins one block of a decomposed 2D grid to the others (issue 27):
// the sides that face another block, whose ghost cells come from that
// block's owned cells instead of a boundary condition (OpenFOAM's processor
// patches), and the reductions a step needs over all blocks. The solver
// stays free of MPI; swe/parallel implements this over MPI ranks.
class SubdomainLink {
 public:
  virtual ~SubdomainLink() = default;

  // x_min, x_max, y_min, y_max: true where another block lies across.
  virtual std::array<bool, 4> linked_sides() const = 0;
  // Fills the two ghost layers across the linked sides of each array (the
  // block's cells with two ghost layers, x fastest) from the neighbours.
  // Every block calls it together (collective).
  virtual void fill_ghosts(std::span<const std::span<double>> arrays) = 0;
  // The largest of every block's `local` (collective; exact).
  virtual double max(double local) = 0;
  // Every block's `values` summed, in place (collective).
  virtual void sum(std::span<double> values) = 0;
};

}  // namespace swe

#pragma once

#include <array>
#include <span>

namespace ice {

// What joins one block of a grid decomposed over MPI ranks to the others
// (issue 27); the solver stays free of MPI, ice/parallel implements this.
//
// A block's IceSolver runs on its block widened by ghost layers toward each
// neighbouring block, and steps the ghost cells too. Its widened edge is a
// wall, which spoils the cells next to it; a step's explicit stages carry
// that fewer cells inward than there are ghost layers, so the owned cells
// compute what a single grid would. The link refreshes the ghosts from
// their owners after the pressure solve (dP) and at the end of every step
// (everything the next step reads), and reduces what the step decides
// together (its Courant number, a refused step) or reports.
template <int Dim>
class BlockLink {
 public:
  using Range = std::array<int, 2>;  // [begin, end) of cell indices

  virtual ~BlockLink() = default;

  // The cells this block owns, in the solver's (widened) grid.
  virtual std::array<Range, static_cast<std::size_t>(Dim)> owned_cells() const = 0;
  // Fills the ghost cells of each field (one value per cell of the widened
  // grid) from their owners. Every block calls it together.
  virtual void fill_ghosts(std::span<const std::span<double>> fields) = 0;
  // The largest of every block's `local` (collective; exact).
  virtual double max(double local) = 0;
  // Every block's `values` summed, in place (collective).
  virtual void sum(std::span<double> values) = 0;
};

}  // namespace ice

#pragma once

#include <array>
#include <memory>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "swe/boundary.hpp"
#include "swe/solver.hpp"
#include "swe/subdomain_link.hpp"

namespace swe {

// The 2D (plan-view) shallow-water equations on a uniform Cartesian grid of
// cells[0] x cells[1] cells of size spacing from origin: HLLC (or Roe/HLL)
// fluxes across x and y faces, MUSCL slopes, hydrostatic reconstruction
// (well-balanced with dry cells), SSP-RK2, semi-implicit Manning friction.
// The x and y directions are treated by the same code with the components
// swapped, so a solution symmetric under x <-> y stays symmetric.
struct Grid2d {
  std::array<double, 2> origin{0.0, 0.0};
  std::array<double, 2> spacing{1.0, 1.0};
  std::array<int, 2> cells{1, 1};
};

// The block of `grid` of cells[d] cells from cell begin[d] on.
Grid2d sub_grid(const Grid2d& grid, std::array<int, 2> begin, std::array<int, 2> cells);

// The grid's cells as a coupling mesh (a cell-centred UniformGrid).
cosim::MeshGeometry cell_mesh(const Grid2d& grid);
// The cell holding (x, y), x fastest, or the cell count when outside: cells
// are closed below, open above, except that the upper edges of the domain
// belong to the last cells.
std::size_t cell_at(const Grid2d& grid, double x, double y);

struct Boundaries2d {
  Boundary x_min, x_max, y_min, y_max;
};

// Solver2d. Ghost cells: walls mirror the interior (bed included) with the normal
// velocity negated; the other kinds copy the adjacent cell (see boundary.hpp;
// inflow into a dry cell uses the critical depth (q^2/g)^(1/3)).
// cell_at: cells are closed below, open above, except that the upper edges of
// the domain belong to the last cells.
//
// A block of a grid decomposed over several processes (issue 27) is a
// Solver2d of the block's cells with a SubdomainLink: the ghost cells of the
// sides it links come from the neighbouring blocks (the boundaries given for
// those sides are ignored), and the stable time step and the totals are
// reduced over every block. The blocks' states are then bit-identical to
// the whole grid's on one process (each cell sees the same neighbours and
// the same dt); the totals agree to round-off (the order of the sum).
//
// A stage sweeps the grid row by row (faces computed once, in vectorised
// loops over a row); rows are split over OpenMP threads above 8192 cells,
// with the same bits on any thread count.
class Solver2d final : public Solver {
 public:
  // Throws cosim::InputError for a non-positive spacing or cell count (and a
  // non-positive gravity, a Courant number outside (0, 1], a negative
  // fixed_depth).
  Solver2d(Grid2d grid, Physics physics, Scheme scheme, Boundaries2d boundaries,
           std::shared_ptr<SubdomainLink> link = nullptr);
  ~Solver2d() override;

  int dimension() const override { return 2; }
  std::size_t cell_count() const override;
  cosim::MeshGeometry cells() const override;
  double cell_size(std::size_t cell) const override;
  std::size_t cell_at(double x, double y = 0.0) const override;

  void set_state(std::span<const double> h, std::span<const double> hu,
                 std::span<const double> hv) override;
  void set_bed(std::span<const double> bed) override;
  // dt = C_r / max over cells of ((|u| + k c) / dx + (|v| + k c) / dy),
  // c = sqrt(g h), k = 2 for a cell with a dry neighbour (the dry-front
  // speed u + 2c), else 1. The unsplit update is a convex combination of 1D
  // half-cell updates, so depths stay non-negative for C_r <= 1/2.
  // +infinity when every cell is dry.
  double stable_time_step() const override;
  void step(double dt) override;
  void save_state() override;
  void restore_state() override;
  void write_state(cosim::StateFileWriter& out) const override;
  void read_state(const cosim::StateFileReader& in) override;
  // The state the blocks `written` (owned cells of the whole grid of
  // grid_cells cells) of another decomposition wrote into `parts`, joined
  // into this solver's block, which owns the cells `mine` (restart on
  // another count of ranks). Throws cosim::InputError when the parts do not
  // cover the block.
  void read_state(std::span<const cosim::StateFileReader* const> parts,
                  std::span<const std::array<cosim::decomposition::Range, 3>> written,
                  const std::array<std::int64_t, 3>& grid_cells,
                  const std::array<cosim::decomposition::Range, 3>& mine);

  // Views of unpadded copies of the state, refreshed by the first call after
  // a step (the same storage for the solver's life).
  std::span<const double> depth() const override;
  std::span<const double> discharge_x() const override;
  std::span<const double> discharge_y() const override;
  std::span<const double> bed() const override;

  Totals totals() const override;
  const Physics& physics() const override;
  const Scheme& scheme() const override;

  const Grid2d& grid() const;
  // The link to the other blocks of a decomposed grid; null on its own.
  SubdomainLink* link() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swe

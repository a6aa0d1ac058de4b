#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "cosim/io/state_file.hpp"
#include "cosim/mesh.hpp"
#include "swe/physics.hpp"
#include "swe/scheme.hpp"

namespace swe {

// Conserved totals of a shallow-water state.
struct Totals {
  double volume = 0.0;      // sum h |cell|          [m^3] (2D) or [m^2] per unit width (1D)
  double momentum_x = 0.0;  // sum h u |cell|
  double momentum_y = 0.0;  // sum h v |cell| (0 in 1D)
};

// A shallow-water finite-volume solver on its own cells (1D non-uniform line
// or 2D uniform grid), as the swe_fluid application drives it:
//
//   solver.set_state(h, hu, hv);
//   while (t < end) {
//     solver.set_bed(bed);                       // when coupled, each window
//     double dt = std::min(solver.stable_time_step(), ...);
//     solver.step(dt);
//   }
//
// Cells are numbered x fastest. Depths never go negative, dry cells
// (h < dry_depth) carry no momentum, and water volume changes only through
// open boundaries.
class Solver {
 public:
  virtual ~Solver() = default;

  virtual int dimension() const = 0;
  virtual std::size_t cell_count() const = 0;
  // The cells as a coupling mesh: NonUniformLine (1D) or a cell-centred UniformGrid (2D).
  virtual cosim::MeshGeometry cells() const = 0;
  // Length (1D) or area (2D) of a cell.
  virtual double cell_size(std::size_t cell) const = 0;
  // The cell holding a point (x, or x and y), or cell_count() when outside.
  virtual std::size_t cell_at(double x, double y = 0.0) const = 0;

  // Depth, discharges (hv ignored in 1D; may be empty) and bed per cell.
  virtual void set_state(std::span<const double> h, std::span<const double> hu,
                         std::span<const double> hv) = 0;
  // Replaces the bed. The depth of every cell is kept, so the water volume
  // does not change and the free surface moves with the bed (the continuity
  // equation h_t + div(h u) = 0 holds for a moving bed).
  virtual void set_bed(std::span<const double> bed) = 0;

  // Largest stable step for the scheme's Courant number (Zheng et al.,
  // eq. 37); +infinity when no water moves or can move.
  virtual double stable_time_step() const = 0;
  // One step of length dt: second-order MUSCL + hydrostatic reconstruction
  // in space, SSP-RK2 (Heun) in time, then the semi-implicit Manning friction
  // (Zheng et al., eq. 36).
  virtual void step(double dt) = 0;

  // A copy of the complete state (depths, discharges and bed, with the
  // boundary ghosts and the derived values the next step reads), kept by the
  // solver: restore_state() puts it back bit for bit, so a coupling window
  // that must run again starts exactly where its first attempt did. The
  // copy's buffers are reused from one save to the next.
  virtual void save_state() = 0;
  // Throws cosim::Error (internal_error) when no state was saved.
  virtual void restore_state() = 0;
  // The same state in a checkpoint's state file (architecture.md §14), read
  // back bit for bit; read_state() refuses (exit 2) arrays of another grid.
  virtual void write_state(cosim::StateFileWriter& out) const = 0;
  virtual void read_state(const cosim::StateFileReader& in) = 0;

  virtual std::span<const double> depth() const = 0;
  virtual std::span<const double> discharge_x() const = 0;
  virtual std::span<const double> discharge_y() const = 0;  // empty in 1D
  virtual std::span<const double> bed() const = 0;

  virtual Totals totals() const = 0;
  virtual const Physics& physics() const = 0;
  virtual const Scheme& scheme() const = 0;
};

}  // namespace swe

#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosim/io/run_size.hpp"
#include "swe/boundary.hpp"
#include "swe/case/bed_shape.hpp"
#include "swe/case/initial_condition.hpp"
#include "swe/physics.hpp"
#include "swe/scheme.hpp"
#include "swe/solver.hpp"
#include "swe/solver_1d.hpp"
#include "swe/solver_2d.hpp"
#include "swe/two_phase/two_phase_spec.hpp"

namespace swe {

// A free-surface gauge: eta, h and the speed at a point, every output.gauge_every.
struct Gauge {
  std::string name;
  double x = 0.0;
  double y = 0.0;
};

// The pressure part of the traction the water exerts on the bed.
enum class BedPressure {
  // p = rho g h, normal to the bed: per unit horizontal area (p dB/dx[, p dB/dy], -p).
  // Exactly the reaction of the bed source -g h grad B the water feels.
  hydrostatic,
  // The waves' push, p = rho g max(0, eta - eta_0) on wet cells, eta_0 the
  // initial free surface above the cell, vertical only (Zheng et al., eq. 10
  // with eta_0 = h_0 + B_0, as used in their Secs. 4.3-4.4: the soil's weight
  // is total and the water's initial load is never applied, so a trough or
  // the water draining off the soil does not pull on it).
  excess,
};

struct CouplingSpec {
  bool reads_bed = true;        // bed_elevation, per cell [m]
  bool writes_traction = true;  // bed_traction, dimension + 1 components [Pa]
  // Two-phase, coupled to a depth-averaged mass: its columns per cell
  // (column_volume, column_mass, column_momentum, structured_mass,
  // released_fluid_volume) in; the drag's impulse on them
  // (momentum_exchange_impulse) and the water's surface
  // (free_surface_elevation) out.
  bool reads_solid_layer = false;
  bool writes_impulse = false;
  bool writes_free_surface = false;
  BedPressure pressure = BedPressure::hydrostatic;
  std::vector<double> initial_surface;  // eta_0 per cell for `excess`, set when the run starts [m]
};

struct CaseDescription {
  std::filesystem::path file;
  std::string name;
  std::uint64_t config_hash = 0;
  int dimension = 1;

  std::vector<double> edges;  // 1D cells
  Grid2d grid;                // 2D cells
  Boundaries1d boundaries_1d;
  Boundaries2d boundaries_2d;
  Physics physics;
  Scheme scheme;
  BedShape bed;
  InitialCondition initial;

  double end_time = 0.0;
  double min_time_step = 1e-9;
  double max_time_step = 0.0;  // 0: no limit beyond stability
  double window = 0.0;         // standalone coupling window; 0: the whole run

  double output_every = 0.0;  // snapshots; 0: start and end only
  bool snapshots = true;
  double gauge_every = 0.0;  // 0: every step
  std::vector<Gauge> gauges;
  int threads = 0;  // 0: OpenMP's default

  CouplingSpec coupling;
  std::optional<TwoPhaseSpec> two_phase;  // absent: single-phase
  cosim::RunSize size;                    // its cells and their memory (set by the loader)
};

// The solver the case describes, with its bed and initial water laid (in
// two-phase mode over bed + the initial solid layer's depth).
std::unique_ptr<Solver> make_solver(const CaseDescription& description);

// A block of the case's 2D grid, for a run decomposed over ranks: its cells
// in the whole grid and its link to the other blocks.
struct GridBlock {
  std::array<int, 2> begin{0, 0};
  std::array<int, 2> cells{0, 0};
  std::shared_ptr<SubdomainLink> link;
};
// The solver of that block, with the case's bed and water in its cells
// (the values at the cells' centres in the whole grid, so that every block
// holds the whole grid's values bit for bit). Single-phase only.
std::unique_ptr<Solver> make_block_solver(const CaseDescription& description,
                                          const GridBlock& block);

}  // namespace swe

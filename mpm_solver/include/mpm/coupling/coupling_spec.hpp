#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"

// The `coupling:` block of an mpm_case file: which meshes the MPM declares
// to the coupler and which fields it writes and reads on them.
//
//   coupling:
//     exchange_grid:                 # porous soil <-> a 3D/2D fluid (mesh mpm_grid)
//       factor: 1                    # MPM cells per exchange cell and direction
//       writes: [solid_fraction, solid_velocity, solid_bulk_density, permeability]
//       reads: [pore_pressure, momentum_exchange_impulse]
//                                    # thermal cases: also solid_temperature,
//                                    # solid_heat_capacity / heat_exchange_energy
//       held_density_factor: 1.0e30
//       hold_at_fixed_faces: true
//       held_bodies: []
//       initial_pore_pressure: 0.0
//     surface:                       # seabed <-> shallow water (mesh mpm_surface)
//       cells: [80]                  # per horizontal direction
//       writes: [bed_elevation]
//       reads: [bed_traction]
//       bed_bodies: []               # bodies forming the bed; empty: all
//       strips: 4                    # 3D: sample lines per cell across y
//
// The job must send every field listed under `reads` (the coupler refuses a
// participant that reads a field nobody sends); fields written that the job
// does not exchange are sent and ignored.
namespace mpm::coupling {

struct ExchangeGridSpec {
  int factor = 1;
  std::vector<std::string> writes;
  std::vector<std::string> reads;
  // Cells whose solid is held (rigid bodies, held bodies, fixed faces) are
  // written with solid_bulk_density x this factor, so the coupler's implicit
  // exchange treats that solid as immovable.
  double held_density_factor = 1e30;
  bool hold_at_fixed_faces = true;
  std::vector<std::string> held_bodies;
  double initial_pore_pressure = 0.0;  // read until the first exchange, and standalone [Pa]

  bool writes_field(const std::string& f) const;
  bool reads_field(const std::string& f) const;
};

struct SurfaceSpec {
  std::vector<int> cells;  // Dim - 1 entries
  std::vector<std::string> writes;
  std::vector<std::string> reads;
  std::vector<std::string> bed_bodies;  // empty: every body
  int strips = 4;

  bool writes_field(const std::string& f) const;
  bool reads_field(const std::string& f) const;
};

struct CouplingSpec {
  std::optional<ExchangeGridSpec> exchange_grid;
  std::optional<SurfaceSpec> surface;
};

// Schema of the `coupling` block (for the case schema and --help-config).
cosim::config::Schema coupling_schema();

// Validates and reads a `coupling` block; with a dimension (2 or 3) also
// checks the surface cell count against it (attach_coupling checks again).
// `heat_conduction` (the case's thermal.enabled) adds the thermal fields to
// the exchange grid's default writes and reads; without it they are
// refused at their keys.
CouplingSpec read_coupling(const cosim::config::Node& node, int dimension = 0,
                           bool heat_conduction = false);

}  // namespace mpm::coupling

#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cosim/io/run_size.hpp"

namespace openfoam {

using Vector3 = std::array<double, 3>;

// One of the two fluids of the VOF case (water and air).
struct FluidProperties {
  double density = 0.0;    // [kg/m^3]
  double viscosity = 0.0;  // dynamic [Pa s]; OpenFOAM takes nu = viscosity / density
};

// What a side of the generated box is.
enum class SideKind {
  wall,        // no slip: U = 0, zero-gradient water fraction, fixedFluxPressure
  slip,        // free slip: zero normal velocity, tangential copied
  atmosphere,  // open top: total pressure 0, inflow of air only
  pressure,    // a fixed pressure (p_rgh) with water flowing in or anything out
};

const char* to_string(SideKind kind);

struct WaterBox {
  Vector3 lower{};
  Vector3 upper{};
};

// A complete blockMesh case made from the YAML: one hexahedral block of
// uniform cells (x fastest, then y, then z, as blockMesh numbers them); in 2D
// one cell thick along z with empty front and back.
struct GeneratedCase {
  int dimension = 2;
  Vector3 origin{};
  Vector3 upper{};
  std::array<int, 3> cells{1, 1, 1};
  Vector3 gravity{};
  FluidProperties water;
  FluidProperties air;
  double surface_tension = 0.07;        // [N/m]
  std::vector<WaterBox> water_regions;  // cells whose centre lies inside start as water
  std::array<SideKind, 6> sides{SideKind::wall, SideKind::wall, SideKind::wall,
                                SideKind::wall, SideKind::wall, SideKind::wall};
  std::array<double, 6> side_pressure{};  // p_rgh of a `pressure` side [Pa]
  double initial_pressure = 0.0;          // p_rgh inside at the start [Pa]

  std::size_t cell_count() const;
  Vector3 spacing() const;
};

// How the MPM soil enters OpenFOAM (coupled runs).
enum class SoilModel {
  parcels,         // MPPICInterFoam's cloud, one parcel per cell (cloud/soil_cloud.hpp)
  porosity_zones,  // interFoam's porosity source on zones (rigid porous structures)
};

struct SoilSettings {
  SoilModel model = SoilModel::parcels;
  int zones = 8;                         // porosity_zones: at most this many zones (one d each)
  double parcel_density = 2.65e6;        // rho_p [kg/m^3]: the drag cannot move the parcels
  double max_solid_fraction = 0.99;      // alphaMax: alphac >= 1 - alphaMax
  double minimum_solid_fraction = 1e-6;  // cells with less soil get no parcel
  // The water the moving soil displaces (see SoilCoupling): the parcels move
  // at U_s / n and the fluid velocity is shifted back by phi_s U_s / n.
  bool displaced_water = true;
};

// A point whose cell's values are recorded every window (gauges.csv).
struct Gauge {
  std::string name;
  Vector3 point{};
};

// A wave gauge of a generated case: the water surface's height over the
// floor at (x, z), origin_y + sum of the column's water fraction x dy.
struct WaveGauge {
  std::string name;
  double x = 0.0;
  double z = 0.0;
};

// A `kind: openfoam_case` file (openfoam_adapter --config).
struct CaseDescription {
  std::filesystem::path file;
  std::uint64_t config_hash = 0;
  std::string name;
  std::string solver = "interFoam";  // the OpenFOAM application run each window
  SoilSettings soil;                 // MPPICInterFoam only
  // Exactly one of the two: a case made from the YAML, or a user's case
  // directory (copied into the run directory, checked up front).
  std::optional<GeneratedCase> generate;
  std::filesystem::path directory;
  double end_time = 0.0;
  double time_step = 0.0;  // fixed OpenFOAM deltaT [s]
  // Standalone, OpenFOAM is restarted every `window` (at least at every
  // snapshot); coupled, the job's window applies. Each must be a whole
  // number of time steps.
  double window = 0.0;
  double output_every = 0.0;           // snapshot interval; 0: start and end only
  bool keep_time_directories = false;  // keep every window's time directory
  double window_timeout = 600.0;       // [s] of wall time for one start of the solver
  std::vector<Gauge> gauges;
  std::vector<WaveGauge> wave_gauges;
  // Parallel OpenFOAM: decomposed once (method simple, `split` cells blocks
  // per direction, their product the process count), run under mpirun.
  // Without the case's `parallel.split`, the run chooses the split from the
  // mesh (choose_split).
  int processes = 1;
  std::array<int, 3> split{1, 1, 1};
  bool split_given = false;
  cosim::RunSize size;  // its cells and the memory of the adapter and OpenFOAM (set by the loader)

  bool has_cloud() const { return solver == "MPPICInterFoam"; }
};

}  // namespace openfoam

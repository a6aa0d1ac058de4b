#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosim/io/run_size.hpp"
#include "mpm/core/tensor.hpp"
#include "mpm/material/material.hpp"
#include "mpm/shape/shape_kernel.hpp"

// Everything a run of the MPM solver needs, as read from a `kind: mpm_case`
// YAML file (see load_case) or built by a test. Vectors are 3D with unused
// trailing components in 2D; the solver converts to its dimension.
namespace mpm {

enum class UpdateScheme {
  usl,   // update stress last
  musl,  // modified USL: stresses from the re-mapped grid velocity (Pan et al. 2021, Sec. 3)
};

enum class LockingMitigation {
  none,
  bbar,  // cell-averaged volumetric strain increment (Zheng et al., Sec. 3.1)
  fbar,  // cell-averaged volume change of the deformation gradient increment
};

// The GIMP particle domain (half-lengths l_p): kept at its initial size
// (uGIMP), or stretched along the axes with the point's deformation,
// l_p,i = l_p0,i |F_ii| (cpGIMP, Bardenhagen and Kober 2004; the axis-aligned
// simplification of the convected domain of Sadeghirad et al. 2011). Only the
// gimp shape reads the domain.
enum class GimpDomain { initial, deformed };

struct GridSpec {
  Vec3d origin = Vec3d::Zero();
  Vec3d spacing = Vec3d::Ones();
  std::array<int, 3> cells{1, 1, 1};
};

// Boundary condition of one face of the grid, on the grid values that lie on it.
struct FaceCondition {
  enum class Kind { free, fixed, slip, frictional };
  Kind kind = Kind::free;
  double friction = 0.0;  // Coulomb coefficient for `frictional`
};
// Faces in the order x-, x+, y-, y+, z-, z+.
using FaceConditions = std::array<FaceCondition, 6>;

// A tabulated function of time, linear between rows, constant beyond the ends.
struct TimeSeries {
  std::vector<double> time;
  std::vector<Vec3d> value;
  Vec3d at(double t) const;
};

enum class PermeabilityModel {
  constant,
  kozeny_carman_pan,   // Pan et al. 2021, eq. 76: k = D50^2 n^3 / (150 (1 - n)^2)
  kozeny_carman_tran,  // Tran et al., MPMICE, eq. 32: k = d^2 (1 - phi_s)^3 / (180 phi_s^2)
};

struct PorousSpec {
  double porosity = 0.0;    // initial n0 [-]
  double grain_size = 0.0;  // D50 [m]
  PermeabilityModel permeability_model = PermeabilityModel::kozeny_carman_pan;
  double permeability = 0.0;   // [m^2], for `constant`
  double max_porosity = 0.99;  // cap of Pan et al. 2021, text after eq. 76
};

// Geostatic initial effective stress: sigma'_v = -gamma' (surface - z),
// sigma'_h = K0 sigma'_v (tension positive).
struct GeostaticStress {
  double k0 = std::numeric_limits<double>::quiet_NaN();  // NaN: Jaky 1 - sin(phi), or nu/(1-nu)
                                                         // when frictionless
  double unit_weight = std::numeric_limits<double>::quiet_NaN();  // NaN: rho |g|
  std::optional<double>
      surface;  // elevation of the free surface; default: top of the body above each point
};

// How a body moves: deformable (its material decides), or rigid with a
// velocity that is fixed (zero), prescribed by a time series (a shaking
// table), or free (translation under gravity and contact forces).
struct RigidMotion {
  enum class Kind { fixed, prescribed, free };
  Kind kind = Kind::fixed;
  TimeSeries velocity;  // for `prescribed`
};

// Particle mass is the material density times the particle volume; for a
// porous body the material density is the grain density and the mass is
// rho_s (1 - n0) V (the solid phase only, as in mixture theory). A body is
// thermal when it has thermal properties (thermal_properties below).
struct BodySpec {
  std::string name;
  int material = -1;  // index into CaseDescription::materials; -1 for rigid bodies
  std::optional<RigidMotion> rigid;
  std::vector<Vec3d> positions;  // seeded particles
  std::vector<double> volumes;
  std::vector<Vec3d> half_lengths;  // particle domain half-lengths (GIMP) [m]
  Vec3d initial_velocity = Vec3d::Zero();
  std::optional<PorousSpec> porous;
  std::optional<GeostaticStress> geostatic;
  double density_override =
      std::numeric_limits<double>::quiet_NaN();       // rigid bodies: their density
  std::optional<ThermalProperties> thermal_override;  // rigid bodies: their thermal properties
  double initial_temperature = 293.15;                // [K]
};

struct ContactSpec {
  bool enabled = false;   // false: one velocity field for all bodies (no-slip)
  double friction = 0.0;  // default coefficient for every pair
  std::map<std::pair<int, int>, double> pair_friction;  // (body a < body b) -> coefficient
  double friction_between(int a, int b) const;
};

// A surface load on a set of particles: a traction vector or a pressure
// acting against the outward normal of `face` (0..5 as FaceConditions);
// the force on a particle is the load times its face area.
struct LoadSpec {
  std::string name;
  std::vector<std::size_t> particles;  // global particle indices
  int face = 3;                        // y+ by default
  std::optional<Vec3d> traction;       // [Pa]
  std::optional<double> pressure;      // [Pa]
  double ramp_time = 0.0;              // ramp from 0 [s]
  // How the load rises over ramp_time: linear (at a constant rate), or
  // cycloidal, t/T - sin(2 pi t/T) / (2 pi), whose rate starts and ends at 0.
  enum class RampShape { linear, cycloidal } ramp_shape = RampShape::linear;

  // The share of the load applied at `time`.
  double ramp_factor(double time) const;
};

// A probe writes one CSV row per output of a quantity of one particle
// (the one nearest to `position` in `body` at start).
struct ProbeSpec {
  std::string name;
  int body = 0;
  Vec3d position = Vec3d::Zero();
  std::size_t particle = 0;  // resolved by the loader
};

// Temperature condition of one grid face, on the grid values that lie on it.
struct FaceTemperature {
  enum class Kind { insulated, fixed };
  Kind kind = Kind::insulated;
  double temperature = 0.0;  // [K], for `fixed`
};

// Heat conduction in the thermal bodies (Tran et al., MPMICE, eqs. 55-56,
// 92). The loader enables it when a body is thermal, unless the case says
// otherwise; faces in the order of FaceConditions.
struct ThermalSpec {
  bool enabled = false;
  std::array<FaceTemperature, 6> faces;
};

struct TimeSpec {
  double end_time = 1.0;
  double safety_factor = 0.5;    // alpha of Zheng et al., eq. 23
  double min_time_step = 1e-12;  // a step below this ends the run (exit 4)
  double max_time_step = std::numeric_limits<double>::infinity();
  double window = 0.0;  // standalone coupling window [s]; 0: none
};

struct OutputSpec {
  double every = 0.0;        // snapshot interval [s]; 0: only first and last
  bool grid = false;         // also grid snapshots
  double probe_every = 0.0;  // probe interval [s]; 0: every snapshot
};

struct CaseDescription {
  std::filesystem::path file;
  std::string name;
  int dimension = 2;
  GridSpec grid;
  ShapeKind shape = ShapeKind::gimp;
  UpdateScheme scheme = UpdateScheme::musl;
  double flip_fraction = 0.99;  // 1: pure FLIP, 0: pure PIC
  LockingMitigation locking = LockingMitigation::none;
  GimpDomain gimp_domain = GimpDomain::initial;
  TimeSpec time;
  Vec3d gravity = Vec3d::Zero();
  double gravity_ramp_time = 0.0;
  double damping = 0.0;  // optional local non-viscous damping coefficient (0 = none)
  std::vector<std::shared_ptr<const Material>> materials;
  std::vector<std::string> material_names;
  std::vector<BodySpec> bodies;
  ContactSpec contact;
  FaceConditions boundaries;
  ThermalSpec thermal;
  std::vector<LoadSpec> loads;
  std::vector<ProbeSpec> probes;
  OutputSpec output;
  int threads = 0;      // 0: OpenMP default
  cosim::RunSize size;  // the particles seeded, the grid and their memory (set by the loader)
};

// The thermal properties of a body: its material's, or a rigid body's own;
// null when the body is not thermal.
const ThermalProperties* thermal_properties(const CaseDescription& description,
                                            const BodySpec& body);
bool has_thermal_body(const CaseDescription& description);

}  // namespace mpm

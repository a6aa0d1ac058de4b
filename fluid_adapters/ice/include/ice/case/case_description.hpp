#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cosim/io/run_size.hpp"
#include "ice/advection/limiter.hpp"
#include "ice/eos/pressure_equilibration.hpp"
#include "ice/io/state_output.hpp"
#include "ice/pressure/pressure_solver.hpp"
#include "ice/solver/fluid_material.hpp"
#include "ice/solver/side_condition.hpp"

namespace ice {

using Vector3 = std::array<double, 3>;

// A shape whose cells (by their centres) take a material, pressure,
// temperature and velocity; later regions override earlier ones.
struct Region {
  enum class Shape { box, sphere };
  Shape shape = Shape::box;
  Vector3 lower{}, upper{};  // box
  Vector3 centre{};          // sphere (a disc in 2D, an interval in 1D)
  double radius = 0.0;
  int material = 0;
  std::optional<double> pressure;     // [Pa]; none: the initial pressure
  std::optional<double> temperature;  // [K]
  std::optional<Vector3> velocity;    // [m/s]

  bool contains(const Vector3& point, int dimension) const;
};

struct InitialDescription {
  int fill = 0;                          // material of cells outside every region
  std::optional<double> pressure;        // [Pa]; none: hydrostatic
  double reference_pressure = 101325.0;  // hydrostatic: on the side gravity points away from [Pa]
  double temperature = 293.15;           // [K]
  Vector3 velocity{};                    // [m/s]
  std::vector<Region> regions;
  double minimum_volume_fraction = 1e-6;  // of every material absent from a cell
};

struct NumericsDescription {
  double cfl = 0.4;
  bool acoustic = false;  // the sound speed enters the time-step limit
  double initial_time_step = 1e-5;
  double min_time_step = 1e-10;
  double max_time_step = 0.0;  // 0: no limit
  double max_step_growth = 1.2;
  Limiter limiter = Limiter::van_leer;
  PressureSolverOptions pressure;
  // Who solves the pressure equation: the built-in solver (one process) or
  // PETSc (any number of ranks); none given: built-in on one process, PETSc
  // on several. With PETSc: its preconditioner (pfmg, the default in 2D
  // and 3D; boomeramg, the default in 1D; gamg, jacobi) and further options
  // (prefix ice_pressure_).
  enum class PressureSolverKind { builtin, petsc };
  std::optional<PressureSolverKind> pressure_solver;
  std::string petsc_preconditioner = "pfmg";
  std::string petsc_options;
  EquilibrationOptions equilibration;
  double smagorinsky_constant = 0.0;  // 0: no turbulence model
};

// How ice_fluid takes part in a coupled run with a porous solid (unused
// standalone).
struct CouplingDescription {
  // true: the fluid-solid drag is solved in each step with the coupler's
  // drag_coefficient (`drag: ice`; the job's momentum_exchange.solved_by:
  // fluid); false: the coupler solves it and sends momentum_exchange_impulse.
  bool drag_in_solver = false;
  double minimum_porosity = 0.05;  // floor of n = 1 - phi_s received
  // The viscosity the received drag coefficient is for [Pa s]; each fluid's
  // share is scaled by its own over it (IceSolver::set_drag_viscosity). 0:
  // as received.
  double drag_viscosity = 0.0;
  // true: write fluid_temperature and fluid_heat_capacity and read the heat
  // of the coupler's energy exchange (`heat_exchange_energy`).
  bool heat_exchange = false;
};

struct CaseDescription {
  std::filesystem::path file;
  std::string name;
  std::uint64_t config_hash = 0;
  int dimension = 1;
  Vector3 origin{}, upper{};
  std::array<int, 3> cells{1, 1, 1};
  Vector3 gravity{};
  std::vector<FluidMaterial> materials;
  ExchangeCoefficients exchange;
  InitialDescription initial;
  std::vector<SideCondition> sides;  // 2 per dimension: x_min, x_max, y_min, ...
  NumericsDescription numerics;
  double end_time = 0.0;
  double window = 0.0;        // the standalone coupling window [s]; 0: the whole run
  double output_every = 0.0;  // 0: start and end only
  bool snapshots = true;
  double gauge_every = 0.0;  // 0: every step
  std::vector<GaugePoint> gauges;
  std::vector<WaveGauge> wave_gauges;
  int threads = 0;
  CouplingDescription coupling;
  cosim::RunSize size;  // its cells and their memory (set by the loader)
};

}  // namespace ice

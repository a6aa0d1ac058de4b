#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "ice/advection/advector.hpp"
#include "ice/advection/limiter.hpp"
#include "ice/diffusion/diffusion.hpp"
#include "ice/eos/pressure_equilibration.hpp"
#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"
#include "ice/pressure/pressure_solver.hpp"
#include "ice/pressure/pressure_system_solver.hpp"
#include "ice/solver/block_link.hpp"
#include "ice/solver/fluid_material.hpp"
#include "ice/solver/fluid_state.hpp"
#include "ice/solver/saved_state.hpp"
#include "ice/solver/side_condition.hpp"

namespace ice {

struct IceSolverOptions {
  Limiter limiter = Limiter::van_leer;
  PressureSolverOptions pressure;
  EquilibrationOptions equilibration;
  // A step whose final face velocities give some cell sum_d |U_d| dt / dx_d
  // above this is rejected (the advection would not stay bounded) and must
  // be retried with a shorter dt.
  double max_courant = 1.0;
  // Return the kinetic energy the advection dissipates to the internal
  // energy, so that advection conserves each material's total energy (the
  // internal-energy form otherwise under-heats shocks: Sod's post-shock
  // density comes out 3 % high at 400 cells).
  bool conserve_total_energy = true;
  // Smagorinsky's C_s (Tran et al., MPMICE, eqs. 17-19); 0: no turbulence model.
  double smagorinsky_constant = 0.0;
};

enum class PorosityChange { compress, displace, fill_pores };

// A coupled solid whose bulk density exceeds this [kg/m3] is held: the solid
// solver marks rigid bodies so (mpm_solver: their density x 1e30). It takes
// the drag with infinite inertia and no solid crosses its cells' faces within
// a window.
inline constexpr double held_solid_bulk_density = 1e20;

struct StepReport {
  bool accepted = true;
  double courant = 0.0;         // max over cells and materials of sum_d |U_FC,d| dt / dx_d
  int pressure_iterations = 0;  // CG iterations of the implicit pressure
  double pressure_residual = 0.0;
  int equilibration_iterations = 0;  // most Newton iterations in a cell (end of step)
  // max over cells of |sum_f rhobar_f v_f - n| after advection: how far the
  // advected specific volumes (eqs. 75-84) drift from filling the pores.
  double volume_closure = 0.0;
};

// Conserved totals of one material over the domain.
struct MaterialTotals {
  double mass = 0.0;                 // [kg] (per metre in 2D, per m2 in 1D)
  std::array<double, 3> momentum{};  // [kg m/s]
  double internal_energy = 0.0;      // sum rhobar c_v T V [J]
  double kinetic_energy = 0.0;       // sum rhobar |U|^2 V / 2 [J]
};

// The native multi-material ICE solver: cell-centred, compressible, with
// the implicit pressure of Tran et al., MPMICE ("Numerical implementation",
// eqs. 42-84 and the appendix eqs. 120-131) on a uniform grid. One step is
// the ordered list in advance(). Every material is present in every cell
// (absent ones at a small volume fraction), so all specific quantities are
// defined; the materials share one pressure.
template <int Dim>
class IceSolver {
 public:
  using Vector = Eigen::Matrix<double, Dim, 1>;
  using Sides = std::array<SideCondition, 2 * Dim>;

  // `state` needs bulk_density, velocity and temperature of every material
  // (and porosity and solid_velocity, or empty for n = 1 and U_s = 0); the
  // rest is computed by equilibrating the pressure with `state.pressure` as
  // the guess (or one atmosphere when empty). Throws std::invalid_argument
  // for sizes that do not fit and cosim::NumericalError (exit 4) for a state
  // the equations of state cannot equilibrate (non-positive density or
  // temperature, volume fractions that cannot fill the pores).
  IceSolver(const CellGrid<Dim>& grid, std::vector<FluidMaterial> materials,
            ExchangeCoefficients exchange, const Sides& sides, const Vector& gravity,
            FluidState<Dim> state, IceSolverOptions options = {});

  const CellGrid<Dim>& grid() const { return grid_; }
  const std::vector<FluidMaterial>& materials() const { return materials_; }
  const FluidState<Dim>& state() const { return state_; }
  const Sides& sides() const { return sides_; }
  const Vector& gravity() const { return gravity_; }
  double time() const { return time_; }
  long steps() const { return steps_; }

  // Sets the porous medium of a coupled run (one value per cell each).
  // compress: the fluids keep their mass and are re-equilibrated to fill the
  // new pores at once (a solid moving in raises the pore pressure by
  // K dn / n); displace: the pores keep their volume now and the next step
  // closes (opens) them by the difference as a source in its pressure
  // equation, as it moves the solid (Tran et al., MPMICE, eq. 107), so the
  // fluids flow out (in) where they can and are compressed only where they
  // cannot; fill_pores: each bulk density is scaled by n_new / n_old, keeping
  // the pressure (a run's first window, when the soil is laid into the fluid).
  void set_porous_medium(std::span<const double> porosity,
                         const std::array<CellField, static_cast<std::size_t>(Dim)>& solid_velocity,
                         PorosityChange change = PorosityChange::displace);

  // The fluid-solid drag of a coupled run solved inside each step (the
  // coupler's `solved_by: fluid`): K per cell [kg m^-3 s^-1], the drag on
  // the fluids per unit volume being K (U_s - U_f), shared among them by
  // their volume fractions, and the solid's bulk density per cell [kg m^-3].
  // The solid then takes part, with that inertia and the velocity of
  // set_porous_medium, in the face exchange of the predicted velocities
  // (Tran et al., MPMICE, eq. 48), held in that of the pressure correction
  // (the pressure equation is then Darcy's where K is large: the solid
  // answers the pressure in the solid solver, with its stresses), and in the
  // cell exchange (eqs. 67-68); its exchange velocity changes only by the
  // drag, its motion (porosity, divergence) is the received velocity. Empty spans switch the drag
  // off. Throws std::invalid_argument for wrong sizes and cosim::NumericalError for a negative or
  // non-finite value.
  void set_solid_drag(std::span<const double> drag_coefficient,
                      std::span<const double> solid_bulk_density);
  bool has_solid_drag() const { return solid_drag_on_; }
  // The viscosity [Pa s] the received drag coefficient was computed for:
  // each fluid's share of it is then scaled by its own viscosity over this
  // one (Darcy's drag is linear in the viscosity: air in the pores of a dry
  // soil is dragged some 55 times less than water). 0, the default: every
  // fluid takes the coefficient as received. Throws std::invalid_argument
  // for a negative value, or a positive one with an inviscid material.
  void set_drag_viscosity(double viscosity);
  // The momentum [kg m/s] the solid has received from the drag since the last
  // call (Dim components per cell, cell-major); then starts again from zero.
  void take_solid_impulse(std::span<double> impulse);

  // The force [N] the pressure exerts on a coupled porous solid in each cell,
  // -phi_s (P_FC,up - P_FC,low) / dx V per direction from the last step's
  // face pressures (Dim components per cell, cell-major): the same gradient
  // the fluids felt, so the mixture as a whole takes -grad P (Tran et al.,
  // MPMICE, eq. 7).
  void solid_pressure_force(std::span<double> force) const;

  // Adds heat [J] to each cell (one value per cell), e.g. what the coupler's
  // energy exchange with a solid gives the fluids over a step: shared among
  // the materials by their heat capacity rhobar c_v, so all warm by the same
  // amount and the total energy grows by exactly the heat; the pressure is
  // then equilibrated again. Throws std::invalid_argument for a wrong size
  // and cosim::NumericalError for a non-finite value or a temperature that
  // would not stay positive.
  void add_heat(std::span<const double> heat);

  // Adds momentum [kg m/s] to each cell (Dim components per cell,
  // cell-major), e.g. the impulse the coupler's implicit fluid-solid exchange
  // gives the fluid over a window. It is shared among the materials in
  // proportion to their mass, so all get the same velocity increment and the
  // total grows by exactly the given amount. Throws std::invalid_argument for
  // a wrong size and cosim::NumericalError for a non-finite value.
  void add_momentum(std::span<const double> momentum);

  // The time step the CFL rule allows: courant / max over cells of
  // sum_d (|U_d| + c) / dx_d, with c the adiabatic sound speed of the
  // materials filling at least 1 % of the cell when `acoustic`, else 0
  // (the implicit pressure step does not need it for stability; shocks need
  // it for accuracy). The face velocities of the last step count too.
  // +infinity when nothing moves and acoustic is off.
  double stable_time_step(double courant, bool acoustic) const;

  // One step of length dt. When the step is rejected (report.accepted
  // false: the face Courant number exceeded options.max_courant, or the
  // pressure work left a material without internal energy) the state is
  // unchanged and a shorter step should be tried. Throws cosim::NumericalError (exit 4) for a
  // pressure solve or equilibration that does not converge and non-finite or non-positive results.
  StepReport advance(double dt);

  // Totals over the owned cells (over every block when linked: collective).
  std::vector<MaterialTotals> totals() const;

  // What each side is to the pressure equation: fixed_pressure sides fix
  // dP, every other side is a wall to it.
  static typename PressureSolver<Dim>::Boundaries pressure_boundaries(const Sides& sides);
  // Solves the pressure equation with `pressure` instead of the built-in
  // PressureSolver (e.g. PETSc's, selected by the case file).
  void use_pressure_solver(std::unique_ptr<PressureSystemSolver<Dim>> pressure);
  // Runs this solver as one block of a decomposed grid (issue 27): grid() is
  // the block widened by the link's ghost layers, the state must hold the
  // ghosts' values as their owners do, and `pressure` solves the pressure
  // equation together with the other blocks, giving dP in the owned cells.
  // The time step, the Courant number, a refused step, the totals and the
  // step's report are then reduced over every block, so all blocks take the
  // same steps (advance, stable_time_step and totals are collective). Throws
  // std::invalid_argument for owned ranges outside the grid.
  void link_blocks(std::shared_ptr<BlockLink<Dim>> link,
                   std::unique_ptr<PressureSystemSolver<Dim>> pressure);
  bool linked() const { return link_ != nullptr; }
  // One flag per cell of grid(): 1 for the cells this block owns (every
  // cell unless linked).
  const std::vector<unsigned char>& owned_cells() const { return owned_; }

  // Copies everything the next steps read into `saved` (reusing its
  // buffers) and back: after restore_state the solver steps exactly as it
  // did after the save, bit for bit (a coupling window that runs again).
  void save_state(SavedIceState<Dim>& saved) const;
  void restore_state(const SavedIceState<Dim>& saved);

  // The last accepted step's face velocities of material m (U^{n+1}_FC)
  // and face pressures (eq. 54), for output and checks.
  const FaceField<Dim>& face_velocity(std::size_t material) const {
    return face_velocity_[material];
  }
  const FaceField<Dim>& face_pressure() const { return face_pressure_; }

 private:
  // The steps of advance(), in order; the exchange steps are defined in
  // src/exchange/.
  void compute_face_velocities(double dt);  // eqs. 44-45
  void porous_face_velocity(std::size_t material, int direction, int face, int lower, int upper,
                            double dt);
  void exchange_face_momentum(double dt);    // eq. 48
  void exchange_two_fluid_faces(double dt);  // eq. 48 for two fluids, no drag: eq. 131
  void assemble_divergence(const std::vector<FaceField<Dim>>& direction);  // eq. 75
  PressureSolution solve_pressure_increment(double dt);                    // eqs. 52-53, 125
  void compute_face_pressure();                                            // eq. 54
  void compute_lagrangian_values(double dt);                               // eqs. 59, 61-62
  void exchange_cell_momentum(double dt);                                  // eqs. 67-68
  bool compute_lagrangian_energy(double dt);              // eqs. 60, 63; false: the step is refused
  void exchange_cell_energy(double dt);                   // eqs. 69-70
  void compute_lagrangian_specific_volume(double dt);     // eqs. 73-76
  void advect_and_update(double dt, StepReport& report);  // eqs. 77-84
  void equilibrate(StepReport* report);                   // eqs. 42-43

  void move_solid(double dt);  // eq. 107
  double face_drag(int lower, int upper, double face_porosity, int direction, int face,
                   const std::vector<FaceField<Dim>>& velocity) const;
  double fluid_upwind_porosity(int lower, int upper, int direction, int face,
                               const std::vector<FaceField<Dim>>& velocity) const;
  void add_viscous_stress(double dt);   // eq. 59's Delta(mU)_tau
  void add_heat_conduction(double dt);  // eq. 60's div q
  double face_courant(double dt) const;
  bool upwind_side_changed(double dt) const;
  // Over every block when linked (collective), else the value itself.
  bool any_block(bool local) const;
  double max_over_blocks(double local) const;
  void refresh_ghosts();  // what the next step reads, from the owners
  void correct_face_velocities(double dt, double sign);
  double face_fraction(std::size_t material, int direction, int face) const;
  void check_state(const FluidState<Dim>& state) const;
  std::size_t count() const { return materials_.size(); }
  bool has_exchange() const { return has_momentum_exchange_; }

  // The members SavedIceState lists are carried from step to step; every
  // other one is rewritten by a step before it is read.
  CellGrid<Dim> grid_;
  std::vector<FluidMaterial> materials_;
  std::vector<const EquationOfState*> eos_;
  ExchangeCoefficients exchange_;
  bool has_momentum_exchange_ = false;
  bool has_heat_exchange_ = false;
  Sides sides_;
  Vector gravity_;
  IceSolverOptions options_;
  FluidState<Dim> state_;
  double time_ = 0.0;
  long steps_ = 0;

  PressureSolver<Dim> pressure_solver_;
  std::unique_ptr<PressureSystemSolver<Dim>> pressure_system_;  // none: pressure_solver_
  std::shared_ptr<BlockLink<Dim>> link_;
  std::vector<unsigned char> owned_;
  Advector<Dim> advector_;
  Diffusion<Dim> diffusion_;
  bool viscous_ = false;
  bool conducting_ = false;
  CellField viscosity_;
  EquilibratedCells equilibrium_;

  // Per material: adiabatic compressibility kappa_s per cell, face
  // velocities (predicted, exchanged, corrected in place) and the face
  // coefficients y of the pressure correction U -= dt y grad dP.
  std::vector<CellField> kappa_;
  std::vector<FaceField<Dim>> face_velocity_;
  std::vector<FaceField<Dim>> face_correction_;
  // Shared per step.
  CellField mixture_kappa_;
  FaceField<Dim> face_density_;      // rho_FC of the pressure solve
  FaceField<Dim> mixture_velocity_;  // sum_f phi_f,FC U_f,FC + phi_s,FC U_s,FC
  FaceField<Dim> face_pressure_;     // eq. 54
  FaceField<Dim> scratch_face_;
  CellField pressure_increment_;
  CellField new_pressure_;
  // Per material, per unit volume: Lagrangian mass, momentum, energy
  // rhobar c_v T, specific volume rhobar v; then advected.
  std::vector<CellField> mass_;
  std::vector<std::array<CellField, static_cast<std::size_t>(Dim)>> momentum_;
  std::vector<CellField> energy_;
  std::vector<CellField> volume_;
  std::vector<CellField> kinetic_;
  std::vector<CellField> lagrangian_temperature_;
  CellField porosity_change_;
  // What set_porous_medium(displace) left for the next step's pressure
  // equation and move_solid: received porosity minus the solver's own.
  CellField porosity_to_displace_;
  CellField displacement_rate_;  // porosity_to_displace_ / dt, the pressure equation's source
  double last_face_rate_ = 0.0;

  // The porous solid: its face velocity and upwind fraction, whose product
  // is the solid volume flux the pressure equation and move_solid share;
  // with set_solid_drag, K and rhobar_s per cell, the velocity it has in the
  // drag exchange (the received one changed by the drag alone; its motion
  // stays the received one: the solid solver moves it) and the impulse it
  // has received.
  FaceField<Dim> solid_face_velocity_;
  FaceField<Dim> solid_face_fraction_;
  std::array<CellField, static_cast<std::size_t>(Dim)> solid_exchange_velocity_;
  // Per fluid material, the volume fraction its face flux carries (the
  // upwind cell's, as the advection of its mass takes it).
  std::vector<FaceField<Dim>> face_fraction_;
  std::vector<FaceField<Dim>> previous_face_velocity_;  // of the last accepted step
  std::vector<FaceField<Dim>> flow_direction_;          // the upwind sides the divergence took
  CellField signed_increment_;
  bool solid_drag_on_ = false;
  // Per fluid material, the factor on its share of the solid drag.
  std::vector<double> drag_share_;
  CellField solid_drag_;
  CellField solid_bulk_density_;
  std::vector<double> solid_impulse_;

  // ---- ice-perf: scratch of the restructured loops (sized on first use) ----
  // Per cell: eq. 54's mixture densities sum_f rhobar_f (compute_face_pressure),
  // the thermal mixture expansion (compute_lagrangian_specific_volume).
  CellField scratch_cell_;
};

extern template class IceSolver<1>;
extern template class IceSolver<2>;
extern template class IceSolver<3>;

}  // namespace ice

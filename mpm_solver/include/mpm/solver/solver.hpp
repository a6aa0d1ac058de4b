#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "cosim/io/state_file.hpp"
#include "mpm/case/case_description.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/solver/grid_partition.hpp"
#include "mpm/solver/solver_state.hpp"

namespace mpm {

// Conserved and dissipated quantities of the particle system [J, kg, kg m/s]
// (per unit depth in 2D).
template <int Dim>
struct Totals {
  double mass = 0.0;
  Vec<Dim> momentum = Vec<Dim>::Zero();
  double kinetic_energy = 0.0;
  double strain_energy = 0.0;  // elastic estimate sum V sigma':sigma'/(2 M)-type, see solver.cpp
  double gravitational_energy = 0.0;  // sum m (-g . x)
  double contact_dissipation =
      0.0;  // work of the contact friction forces (Tran et al., MPMICE, eq. 22)
  double boundary_dissipation = 0.0;  // work removed by frictional grid faces
  double external_work = 0.0;         // work of surface loads and coupling forces
  double internal_work = 0.0;         // stress work sum V sigma : d eps since the start
  // Internal work not stored as elastic energy: plastic (and numerical) dissipation.
  double plastic_dissipation = 0.0;
  // Heat conduction (zero unless the case conducts heat): sum_p m_p c_p T_p,
  // and the heat that came from external sources and through fixed-temperature
  // faces since the start; thermal_energy - external_heat - heat_through_faces
  // stays constant to round-off.
  double thermal_energy = 0.0;
  double external_heat = 0.0;
  double heat_through_faces = 0.0;
};

// The explicit MPM of Zheng et al. (eqs. 13-23) with the USL/MUSL variants
// and PIC/FLIP blend of Pan et al. 2021 (eqs. 70-73). One call to step()
// runs the ordered list of named steps in solver.cpp.
template <int Dim>
class Solver {
 public:
  explicit Solver(const CaseDescription& description);
  // One rank's part of a decomposed run (issue 27): the points of the
  // partition's cell rows and the grid values they touch. Every step then
  // gives each point and each owned grid value the same bits as one process
  // would; totals() are summed over the ranks (equal to round-off), heat
  // conduction included.
  Solver(const CaseDescription& description, std::shared_ptr<GridPartition<Dim>> partition);
  ~Solver();
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // Zheng et al., eq. 23: alpha h / (max_p c_p + max |v_i|), bounded by the
  // case's max_time_step; when the case conducts heat, also by the explicit
  // conduction limit alpha h^2 / (2 Dim max_p k_eff / (rho c)).
  double stable_time_step() const;
  // Advances by dt (<= stable_time_step() for stability; not enforced).
  void step(double dt);
  // On a rank of a decomposed run, after the partition's rows changed (load
  // balance): takes the grid planes of the new rows and moves the points to
  // their new ranks (collective). The state keeps its bits, and so do the
  // steps after. Nothing on one process.
  void repartition();
  // The partition of a decomposed run's rank; nullptr on one process.
  GridPartition<Dim>* partition() const;

  double time() const;
  std::size_t step_count() const;

  // Copies the state the steps carry into `state` (see SolverState), and
  // puts it back: the steps after restore() repeat those after save() bit
  // for bit. Restoring a state never saved, or one of another solver's
  // size, is an internal error.
  void save(SolverState<Dim>& state) const;
  void restore(const SolverState<Dim>& state);
  // The same state in a checkpoint's state file (architecture.md §14), read
  // back bit for bit into a solver built from the same case.
  void write_state(cosim::StateFileWriter& out) const;
  void read_state(const cosim::StateFileReader& in);
  // The state the ranks of a decomposed run wrote into `parts` (each its
  // points and partial energies), whatever count of ranks wrote them: rank
  // `rank` of `ranks` takes the points and energies of parts rank, rank +
  // ranks, ...; the points then go to the ranks that own them now
  // (collective on a decomposed grid). Together they must be the case's.
  void read_state(std::span<const cosim::StateFileReader* const> parts, int rank, int ranks);

  // Coupling and extra physics hook in here. Force sources run each step
  // after the surface loads and add their force [N] to
  // particles().external_force; grid corrections run after the grid
  // velocity update and before boundary conditions and grid-to-particle
  // (e.g. the velocity increment of a momentum exchange).
  // Heat sources run each step before the heat conduction when the case
  // conducts heat and add their heat rate [W] to particles().external_heat.
  using ParticleForceSource = std::function<void(double time, double dt, Particles<Dim>&)>;
  using GridVelocityCorrection = std::function<void(double time, double dt, Grid<Dim>&)>;
  using ParticleHeatSource = std::function<void(double time, double dt, Particles<Dim>&)>;
  void add_particle_force_source(ParticleForceSource source);
  void add_grid_velocity_correction(GridVelocityCorrection correction);
  void add_particle_heat_source(ParticleHeatSource source);

  // This process's points (on a rank: those of its cell rows, in id order).
  Particles<Dim>& particles();
  // The index among them of the point with id `id`, or particles().size()
  // when another rank holds it.
  std::size_t local_index(std::size_t id) const;
  const Particles<Dim>& particles() const;
  const Grid<Dim>& grid() const;
  const CaseDescription& description() const;
  Totals<Dim> totals() const;
  // Total Cauchy stress sigma' - p I of a particle (Tran et al., MPMICE, eq. 3).
  Tensor total_stress(std::size_t particle) const;

  // description().thermal.enabled: temperatures conduct.
  bool conducts_heat() const;

  // Throws NumericalError naming the particle id, body and time when a
  // particle's state is not finite or a particle has left the grid.
  void check_state() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

extern template class Solver<2>;
extern template class Solver<3>;

}  // namespace mpm

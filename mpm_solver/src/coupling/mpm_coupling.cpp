#include "mpm/coupling/mpm_coupling.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <limits>
#include <string>

#include "cosim/error.hpp"
#include "cosim/participant.hpp"
#include "mpm/coupling/bed_elevation.hpp"
#include "mpm/coupling/field_names.hpp"
#include "mpm/coupling/pore_pressure_force.hpp"
#include "mpm/coupling/porous_fields_writer.hpp"
#include "mpm/coupling/thermal_fields_writer.hpp"
#include "mpm/solver/grid_partition.hpp"

namespace mpm::coupling {

namespace {

// A rank's part of the exchange grid (issue 27): it holds every cell, the
// fields being sums over all ranks' points, and owns the rows of exchange
// cells whose first MPM cell row is among its own rows.
template <int Dim>
cosim::MeshPart exchange_part(const ExchangeGrid<Dim>& exchange, int factor,
                              std::array<int, 2> mpm_rows) {
  const cosim::UniformGrid mesh = exchange.mesh();
  const auto first_row_at_or_after = [factor](int mpm_row) {
    return static_cast<std::int64_t>((mpm_row + factor - 1) / factor);
  };
  cosim::Index3 owned_lower{0, 0, 0};
  cosim::Index3 owned_upper = mesh.cells;
  owned_lower[Dim - 1] = first_row_at_or_after(mpm_rows[0]);
  owned_upper[Dim - 1] = first_row_at_or_after(mpm_rows[1]);
  return cosim::MeshPart::box(mesh, {0, 0, 0}, mesh.cells, owned_lower, owned_upper);
}

// A rank's part of the surface: every rank holds every column (the
// surface's values are formed from all ranks' points); the rank of the
// lowest cell rows owns them all.
template <int Dim>
cosim::MeshPart surface_part(const SurfaceGrid<Dim>& surface, std::array<int, 2> mpm_rows) {
  const cosim::UniformGrid mesh = surface.mesh();
  const cosim::Index3 none{0, 0, 0};
  return cosim::MeshPart::box(mesh, none, mesh.cells, none, mpm_rows[0] == 0 ? mesh.cells : none);
}

template <int Dim>
std::span<const double> flat(const std::vector<Vec<Dim>>& v) {
  return {v.empty() ? nullptr : v.front().data(), v.size() * static_cast<std::size_t>(Dim)};
}

}  // namespace

template <int Dim>
struct MpmCoupling<Dim>::State {
  Solver<Dim>& solver;
  std::unique_ptr<CouplingChannel> channel;
  CouplingSpec spec;
  std::vector<BodyRole> roles;
  std::optional<ExchangeGrid<Dim>> exchange;
  std::optional<SurfaceGrid<Dim>> surface;
  CouplingDiagnostics<Dim> diagnostics;
  CouplingDiagnostics<Dim> saved_diagnostics;  // at the start of a window that may run again
  std::vector<std::string> held_warnings;      // until the window is complete
  // On a rank of a decomposed run: what joins its points' shares to the
  // other ranks'.
  SumOverRanks sum_over_ranks;
  MaxOverRanks max_over_ranks;
  GatherOverRanks gather_over_ranks;

  std::vector<double> cell_values;    // scratch for reads
  std::vector<Vec<Dim>> scratch;      // per particle
  std::vector<Vec<Dim>> force;        // per particle [N]
  std::vector<double> particle_heat;  // per particle, this step [J]

  State(Solver<Dim>& s, std::unique_ptr<CouplingChannel> c, CouplingSpec sp)
      : solver(s), channel(std::move(c)), spec(std::move(sp)) {}

  bool exchange_writes(const char* f) const {
    return spec.exchange_grid && spec.exchange_grid->writes_field(f);
  }
  bool exchange_reads(const char* f) const {
    return spec.exchange_grid && spec.exchange_grid->reads_field(f);
  }
  bool surface_writes(const char* f) const { return spec.surface && spec.surface->writes_field(f); }
  bool surface_reads(const char* f) const { return spec.surface && spec.surface->reads_field(f); }

  void add_to_force(const std::vector<Vec<Dim>>& f, double scale) {
    for (std::size_t p = 0; p < force.size(); ++p) force[p] += scale * f[p];
  }

  // The solver's particle force source: reads what the partner sent for
  // this step of dt and adds it to the particles' external force.
  void apply(double dt, Particles<Dim>& particles);
  // The solver's heat source: the step's share of the exchanged heat, as
  // the heat rate E_p / dt of each particle.
  void apply_heat(double dt, Particles<Dim>& particles);
};

template <int Dim>
void MpmCoupling<Dim>::State::apply_heat(double dt, Particles<Dim>& particles) {
  cell_values.resize(exchange->size());
  channel->read_increment(names::heat, dt, cell_values);
  const HeatSplit split =
      split_heat(*exchange, cell_values, particles, particle_heat, sum_over_ranks);
  diagnostics.heat_step = split;
  diagnostics.heat_total.received += split.received;
  diagnostics.heat_total.applied += split.applied;
  diagnostics.heat_total.absorbed += split.absorbed;
  for (std::size_t p = 0; p < particles.size(); ++p)
    particles.external_heat[p] += particle_heat[p] / dt;
}

template <int Dim>
void MpmCoupling<Dim>::State::apply(double dt, Particles<Dim>& particles) {
  namespace n = names;
  force.assign(particles.size(), Vec<Dim>::Zero());
  const bool cell_pressure_force = exchange_reads(n::pore_pressure_force);
  if (exchange_reads(n::pore_pressure)) {
    cell_values.resize(exchange->size());
    channel->read(n::pore_pressure, dt, cell_values);
    const Vec<Dim> total = pore_pressure_force(*exchange, cell_values, particles, roles, scratch);
    if (!cell_pressure_force) {
      diagnostics.pore_pressure_force = total;
      add_to_force(scratch, 1.0);
    }
  }
  if (cell_pressure_force) {
    cell_values.resize(exchange->size() * static_cast<std::size_t>(Dim));
    channel->read(n::pore_pressure_force, dt, cell_values);
    diagnostics.pore_pressure_force =
        split_impulse(*exchange, cell_values, particles, roles, scratch, SplitWeight::solid_volume,
                      sum_over_ranks)
            .applied;
    add_to_force(scratch, 1.0);
  }
  if (exchange_reads(n::impulse)) {
    cell_values.resize(exchange->size() * static_cast<std::size_t>(Dim));
    channel->read_increment(n::impulse, dt, cell_values);
    const auto split = split_impulse(*exchange, cell_values, particles, roles, scratch,
                                     SplitWeight::deformable_mass, sum_over_ranks);
    diagnostics.impulse_step = split;
    diagnostics.impulse_total.received += split.received;
    diagnostics.impulse_total.applied += split.applied;
    diagnostics.impulse_total.absorbed += split.absorbed;
    add_to_force(scratch, 1.0 / dt);
  }
  if (surface_reads(n::bed_traction)) {
    cell_values.resize(surface->size() * static_cast<std::size_t>(Dim));
    channel->read(n::bed_traction, dt, cell_values);
    diagnostics.traction_step = surface_traction(*surface, cell_values, particles, roles, scratch,
                                                 max_over_ranks, sum_over_ranks);
    add_to_force(scratch, 1.0);
  }
  for (std::size_t p = 0; p < particles.size(); ++p) particles.external_force[p] += force[p];
}

template <int Dim>
MpmCoupling<Dim>::MpmCoupling(Solver<Dim>& solver, std::unique_ptr<CouplingChannel> channel,
                              CouplingSpec spec)
    : state_(std::make_shared<State>(solver, std::move(channel), std::move(spec))) {
  State& s = *state_;
  s.roles = body_roles(solver.description(), s.spec);
  if (GridPartition<Dim>* partition = solver.partition()) {
    s.sum_over_ranks = [partition](std::span<double> values) { partition->sum(values); };
    s.max_over_ranks = [partition](std::span<double> values) { partition->max(values); };
    s.gather_over_ranks = [partition](std::span<const double> values) {
      return partition->gather(values);
    };
  }
  if (s.spec.exchange_grid)
    s.exchange = ExchangeGrid<Dim>::covering(solver.grid(), s.spec.exchange_grid->factor);
  if (s.spec.surface) {
    const auto& cells = s.spec.surface->cells;
    if (static_cast<int>(cells.size()) != Dim - 1)
      throw cosim::InputError(
          fmt::format("{}: key 'coupling.surface.cells': a {}D case has {} horizontal "
                      "direction(s), got {} cell count(s)",
                      solver.description().file.string(), Dim, Dim - 1, cells.size()));
    std::array<int, Dim - 1> n{};
    for (std::size_t d = 0; d + 1 < Dim; ++d) n[d] = cells[d];
    s.surface = SurfaceGrid<Dim>::covering(solver.grid(), n);
  }
  if (s.spec.exchange_grid && !solver.conducts_heat()) {
    const auto& g = *s.spec.exchange_grid;
    for (const auto& [key, list] : {std::pair{"writes", &g.writes}, std::pair{"reads", &g.reads}})
      for (const auto& f : *list)
        if (names::is_thermal(f))
          throw cosim::InputError(
              fmt::format("{}: key 'coupling.exchange_grid.{}': {} needs a case that conducts heat",
                          solver.description().file.string(), key, f));
  }
  std::shared_ptr<State> shared = state_;
  solver.add_particle_force_source(
      [shared](double, double dt, Particles<Dim>& particles) { shared->apply(dt, particles); });
  if (s.exchange_reads(names::heat))
    solver.add_particle_heat_source([shared](double, double dt, Particles<Dim>& particles) {
      shared->apply_heat(dt, particles);
    });
}

template <int Dim>
MpmCoupling<Dim>::~MpmCoupling() = default;

template <int Dim>
void MpmCoupling<Dim>::declare() {
  State& s = *state_;
  namespace n = names;
  namespace f = cosim::fields;
  if (s.exchange) {
    if (s.sum_over_ranks) {
      s.channel->declare_mesh({n::exchange_mesh, s.exchange->mesh()},
                              exchange_part(*s.exchange, s.spec.exchange_grid->factor,
                                            s.solver.partition()->owned_rows()));
    } else {
      s.channel->declare_mesh({n::exchange_mesh, s.exchange->mesh()});
    }
    auto write = [&](const f::Field& field, double lo) {
      if (!s.exchange_writes(field.name)) return;
      cosim::FieldSpec spec = field.on(n::exchange_mesh, Dim);
      spec.lower_bound = lo;
      if (&field == &f::solid_fraction) spec.upper_bound = 1.0;
      s.channel->declare_write(spec);
    };
    const double none = -std::numeric_limits<double>::infinity();
    write(f::solid_fraction, 0.0);
    write(f::solid_velocity, none);
    write(f::solid_bulk_density, 0.0);
    write(f::permeability, 0.0);
    write(f::grain_size, 0.0);
    write(f::solid_volume_flux, none);
    write(f::solid_temperature, 0.0);
    write(f::solid_heat_capacity, 0.0);
    auto read = [&](const f::Field& field, double default_value) {
      if (s.exchange_reads(field.name))
        s.channel->declare_read(field.on(n::exchange_mesh, Dim), default_value);
    };
    read(f::pore_pressure, s.spec.exchange_grid->initial_pore_pressure);
    read(f::pore_pressure_force, 0.0);
    read(f::momentum_exchange_impulse, 0.0);
    read(f::heat_exchange_energy, 0.0);
  }
  if (s.surface) {
    if (s.sum_over_ranks) {
      s.channel->declare_mesh({n::surface_mesh, s.surface->mesh()},
                              surface_part(*s.surface, s.solver.partition()->owned_rows()));
    } else {
      s.channel->declare_mesh({n::surface_mesh, s.surface->mesh()});
    }
    if (s.surface_writes(n::bed_elevation))
      s.channel->declare_write(f::bed_elevation.on(n::surface_mesh, Dim));
    if (s.surface_reads(n::bed_traction))
      s.channel->declare_read(f::bed_traction.on(n::surface_mesh, Dim), 0.0);
  }
  write_fields();
  log_held_warnings();
}

template <int Dim>
double MpmCoupling<Dim>::max_time_step() const {
  return state_->channel->max_time_step();
}

template <int Dim>
void MpmCoupling<Dim>::after_step(double dt) {
  const CouplingChannel& channel = *state_->channel;
  if (dt >= channel.max_time_step() - 1e-9 * channel.window_size()) write_fields();
}

template <int Dim>
void MpmCoupling<Dim>::write_fields() {
  State& s = *state_;
  namespace n = names;
  const Particles<Dim>& particles = s.solver.particles();
  const bool porous =
      s.exchange_writes(n::solid_fraction) || s.exchange_writes(n::solid_velocity) ||
      s.exchange_writes(n::solid_bulk_density) || s.exchange_writes(n::permeability) ||
      s.exchange_writes(n::grain_size) || s.exchange_writes(n::solid_volume_flux);
  if (porous) {
    const auto& g = *s.spec.exchange_grid;
    const auto held = held_particles(particles, s.solver.grid(), s.roles,
                                     s.solver.description().boundaries, g.hold_at_fixed_faces);
    const PorousFields f = porous_fields(*s.exchange, particles, s.roles, held,
                                         g.held_density_factor, s.sum_over_ranks);
    if (f.capped_cells > 0)
      s.held_warnings.push_back(fmt::format(
          "mpm coupling: solid fraction above 1 capped in {} exchange cell(s) at t = {:.6g} s",
          f.capped_cells, s.solver.time()));
    s.diagnostics.capped_solid_fraction_cells += f.capped_cells;
    s.diagnostics.overfilled_cells += f.overfilled_cells;
    s.diagnostics.held_cells =
        static_cast<std::size_t>(std::count(f.held.begin(), f.held.end(), 1));
    if (s.exchange_writes(n::solid_fraction)) s.channel->write(n::solid_fraction, f.solid_fraction);
    if (s.exchange_writes(n::solid_velocity)) s.channel->write(n::solid_velocity, f.solid_velocity);
    if (s.exchange_writes(n::solid_bulk_density))
      s.channel->write(n::solid_bulk_density, f.solid_bulk_density);
    if (s.exchange_writes(n::permeability)) s.channel->write(n::permeability, f.permeability);
    if (s.exchange_writes(n::grain_size)) s.channel->write(n::grain_size, f.grain_size);
    if (s.exchange_writes(n::solid_volume_flux))
      s.channel->write(n::solid_volume_flux, f.solid_volume_flux);
  }
  if (s.exchange_writes(n::solid_temperature) || s.exchange_writes(n::solid_heat_capacity)) {
    const ThermalFields f = thermal_fields(*s.exchange, particles, s.sum_over_ranks);
    if (s.exchange_writes(n::solid_temperature))
      s.channel->write(n::solid_temperature, f.solid_temperature);
    if (s.exchange_writes(n::solid_heat_capacity))
      s.channel->write(n::solid_heat_capacity, f.solid_heat_capacity);
  }
  if (s.surface && s.surface_writes(n::bed_elevation))
    s.channel->write(n::bed_elevation, bed_elevation(*s.surface, particles, s.roles,
                                                     s.spec.surface->strips, s.gather_over_ranks));
  ++s.diagnostics.writes;
}

template <int Dim>
void MpmCoupling<Dim>::save_state() {
  state_->saved_diagnostics = state_->diagnostics;
}

template <int Dim>
void MpmCoupling<Dim>::restore_state() {
  state_->diagnostics = state_->saved_diagnostics;
  state_->held_warnings.clear();
}

template <int Dim>
void MpmCoupling<Dim>::log_held_warnings() {
  for (const std::string& warning : state_->held_warnings) spdlog::warn("{}", warning);
  state_->held_warnings.clear();
}

template <int Dim>
const ExchangeGrid<Dim>* MpmCoupling<Dim>::exchange_grid() const {
  return state_->exchange ? &*state_->exchange : nullptr;
}
template <int Dim>
const SurfaceGrid<Dim>* MpmCoupling<Dim>::surface() const {
  return state_->surface ? &*state_->surface : nullptr;
}
template <int Dim>
const std::vector<BodyRole>& MpmCoupling<Dim>::roles() const {
  return state_->roles;
}
template <int Dim>
const CouplingDiagnostics<Dim>& MpmCoupling<Dim>::diagnostics() const {
  return state_->diagnostics;
}

template <int Dim>
std::unique_ptr<MpmCoupling<Dim>> attach_coupling(Solver<Dim>& solver,
                                                  cosim::Participant& participant,
                                                  const CouplingSpec& spec) {
  return std::make_unique<MpmCoupling<Dim>>(
      solver, std::make_unique<ParticipantChannel>(participant), spec);
}

template class MpmCoupling<2>;
template class MpmCoupling<3>;
template std::unique_ptr<MpmCoupling<2>> attach_coupling<2>(Solver<2>&, cosim::Participant&,
                                                            const CouplingSpec&);
template std::unique_ptr<MpmCoupling<3>> attach_coupling<3>(Solver<3>&, cosim::Participant&,
                                                            const CouplingSpec&);

}  // namespace mpm::coupling

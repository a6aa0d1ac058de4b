#include "mpm/solver/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "body_state.hpp"
#include "cosim/error.hpp"
#include "geostatic_stress.hpp"
#include "grid_boundaries.hpp"
#include "grid_contact.hpp"
#include "heat_conduction.hpp"
#include "mpm/particles/particle_state_file.hpp"
#include "mpm/shape/grid_geometry.hpp"
#include "mpm/shape/shape_dispatch.hpp"
#include "mpm/shape/stencil.hpp"
#include "particle_bins.hpp"
#include "stress_update.hpp"

namespace mpm {

template <int Dim>
struct Solver<Dim>::Impl {
  CaseDescription description;
  Grid<Dim> grid;
  GridGeometry<Dim> geometry;
  Particles<Dim> particles;
  std::vector<detail::BodyState<Dim>> bodies;
  std::vector<int> field_of_body;
  detail::ContactFields contact;
  detail::FaceValues faces;
  detail::ParticleBins bins;
  // The odd slabs' partial sums of the arrays particle-to-grid scatters
  // (ParticleBins); zero between scatters.
  std::vector<double> odd_mass;
  std::vector<Vec<Dim>> odd_momentum, odd_force, odd_mass_gradient, odd_remapped;
  // On a rank of a decomposed run: the link to the other ranks.
  std::shared_ptr<GridPartition<Dim>> partition;
  // The scatter's slab of each stored plane of grid values, and the contact
  // impulse per slab and field (slab-major).
  std::vector<std::size_t> slab_of_plane;
  std::vector<Vec<Dim>> impulse_by_slab;
  std::vector<ParticleForceSource> force_sources;
  std::vector<GridVelocityCorrection> grid_corrections;
  std::vector<ParticleHeatSource> heat_sources;
  std::optional<detail::HeatConduction<Dim>> heat;  // when the case conducts heat
  std::vector<Vec<Dim>> impulse_on_field;
  // Cell sums for the volumetric locking mitigation (value, weight).
  std::vector<double> cell_sum;
  std::vector<double> cell_weight;
  std::vector<double> volumetric_increment;   // per particle, scratch
  std::vector<double> stress_work;            // per particle, this step, scratch
  std::vector<Vec<Dim>> initial_half_length;  // for GimpDomain::deformed
  double time = 0.0;
  std::size_t steps = 0;
  AccumulatedEnergy accumulated;
  double initial_strain_energy = 0.0;
  // Faces with a wall keep the points inside; free faces let them leave (an error).
  Vec<Dim> wall_lower;
  Vec<Dim> wall_upper;

  explicit Impl(const CaseDescription& d);
  void allocate_grid(int field_count);
  void restrict_to(std::shared_ptr<GridPartition<Dim>> part);
  void store_planes_of_owned_rows();
  // The stored index of the flat grid value `flat` of field `field`.
  std::size_t stored(int field, std::size_t flat) const {
    return static_cast<std::size_t>(field) * grid.size() + flat - grid.first_value();
  }
  // The slab of the stored value `v` (any field).
  std::size_t slab_of_value(std::size_t v) const { return slab_of_plane[v / grid.plane_size()]; }
  void sum_contact_impulse();
  GridArray array_of(std::vector<double>& v) { return {v.data(), 1}; }
  GridArray array_of(std::vector<Vec<Dim>>& v) { return {v.data()->data(), Dim}; }
  std::size_t local_index(std::size_t id) const;

  Vec<Dim> gravity_at(double t) const;
  int field_of(std::size_t p) const { return field_of_body[particles.body[p]]; }
  const detail::BodyState<Dim>& body_of(std::size_t p) const { return bodies[particles.body[p]]; }
  bool has_rigid_body() const {
    return std::any_of(bodies.begin(), bodies.end(), [](const auto& b) { return b.is_rigid(); });
  }

  // The time step, in order (Uintah style).
  void step(double dt);
  void bin_particles();
  void apply_surface_loads(double dt);
  void apply_coupling_forces(double dt);
  void add_external_work(double dt);
  void set_rigid_velocities(double dt);
  template <class Kernel>
  void interpolate_particles_to_grid(double dt);
  void integrate_grid_momentum(double dt);
  void apply_grid_corrections(double dt);
  void apply_contact_and_boundaries(double dt);
  void apply_heat_sources(double dt);
  template <class Kernel>
  void interpolate_heat_to_grid();
  template <class Kernel>
  void conduct_heat();
  void integrate_grid_temperature(double dt);
  template <class Kernel>
  void interpolate_temperature_change_to_particles();
  template <class Kernel>
  void interpolate_grid_to_particles(double dt);
  template <class Kernel>
  void interpolate_and_remap_velocities();
  template <class Kernel>
  void update_positions_and_stresses(double dt);
  void update_particle_domains();
  void move_rigid_bodies(double dt);

  template <class Kernel>
  Mat<Dim> velocity_gradient(const Stencil<Dim, Kernel>& stencil,
                             const std::vector<Vec<Dim>>& field_velocity, std::size_t offset) const;
  template <class Kernel>
  void update_kinematics_and_stress(double dt, bool use_remapped);

  double stable_time_step() const;
  Totals<Dim> totals() const;
  void check_state() const;
};

namespace {

// Below this many items a loop runs on one thread: thread start-up and
// barriers cost more than the work, and far more on a loaded machine.
constexpr std::size_t parallel_threshold = 8192;
bool worth_threads(std::size_t items) {
  return items >= parallel_threshold;
}

template <int Dim>
Vec<Dim> shrink(const Vec3d& v) {
  return v.template head<Dim>();
}

}  // namespace

template <int Dim>
Solver<Dim>::Impl::Impl(const CaseDescription& d) : description(d) {
  if (d.threads > 0) omp_set_num_threads(d.threads);
  std::array<int, Dim> cells{};
  for (int k = 0; k < Dim; ++k)
    cells[static_cast<std::size_t>(k)] = d.grid.cells[static_cast<std::size_t>(k)];
  grid = make_grid<Dim>(shrink<Dim>(d.grid.origin), shrink<Dim>(d.grid.spacing), cells, d.shape);
  geometry.origin = grid.origin;
  geometry.spacing = grid.spacing;
  geometry.cells = grid.cells;

  // Particles, body by body.
  std::size_t total = 0;
  for (const BodySpec& b : d.bodies) total += b.positions.size();
  particles.resize(total);
  std::size_t next = 0;
  std::vector<double> body_conductivity;
  int deformable_field = -1;
  int field_count = 0;
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    const BodySpec& spec = d.bodies[b];
    detail::BodyState<Dim> state;
    state.name = spec.name;
    state.first = next;
    state.count = spec.positions.size();
    if (spec.rigid) {
      state.rigid = &*spec.rigid;
      state.field = field_count++;
    } else {
      state.material = d.materials.at(static_cast<std::size_t>(spec.material)).get();
      state.p_wave_modulus = state.material->p_wave_modulus();
      if (d.contact.enabled) {
        state.field = field_count++;
      } else {
        if (deformable_field < 0) deformable_field = field_count++;
        state.field = deformable_field;
      }
    }
    const double density = spec.rigid ? spec.density_override : state.material->density();
    const double solid_fraction = spec.porous ? 1.0 - spec.porous->porosity : 1.0;
    const ThermalProperties* thermal = thermal_properties(d, spec);
    body_conductivity.push_back(thermal ? thermal->conductivity : 0.0);
    for (std::size_t k = 0; k < spec.positions.size(); ++k, ++next) {
      const std::size_t p = next;
      particles.position[p] = shrink<Dim>(spec.positions[k]);
      particles.half_length[p] = shrink<Dim>(spec.half_lengths[k]);
      particles.velocity[p] = shrink<Dim>(spec.initial_velocity);
      particles.initial_volume[p] = spec.volumes[k];
      particles.volume[p] = spec.volumes[k];
      particles.mass[p] =
          (std::isfinite(density) ? density : 0.0) * solid_fraction * spec.volumes[k];
      particles.body[p] = static_cast<std::uint32_t>(b);
      particles.temperature[p] = spec.initial_temperature;
      if (thermal) particles.heat_capacity[p] = particles.mass[p] * thermal->specific_heat;
      if (spec.porous) {
        particles.porosity[p] = spec.porous->porosity;
        particles.initial_porosity[p] = spec.porous->porosity;
        particles.grain_size[p] = spec.porous->grain_size;
        particles.permeability[p] = detail::permeability(*spec.porous, spec.porous->porosity);
      }
      if (state.material) {
        MaterialState ms;
        state.material->initialise(ms);
        particles.stress[p] = to_voigt(ms.stress);
        particles.plastic_strain[p] = ms.plastic_strain;
        particles.damage[p] = ms.damage;
        particles.internal[p] = ms.internal;
      }
      state.mass += particles.mass[p];
    }
    if (spec.rigid && spec.rigid->kind == RigidMotion::Kind::prescribed)
      state.rigid_velocity = shrink<Dim>(spec.rigid->velocity.at(0.0));
    if (spec.rigid && spec.rigid->kind == RigidMotion::Kind::free)
      state.rigid_velocity = shrink<Dim>(spec.initial_velocity);
    bodies.push_back(state);
    field_of_body.push_back(state.field);
  }
  if (field_count == 0) field_count = 1;
  allocate_grid(field_count);
  contact.rigid.assign(static_cast<std::size_t>(field_count), false);
  contact.friction.assign(
      static_cast<std::size_t>(field_count),
      std::vector<double>(static_cast<std::size_t>(field_count), d.contact.friction));
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].is_rigid()) contact.rigid[static_cast<std::size_t>(bodies[b].field)] = true;
    for (std::size_t c = 0; c < bodies.size(); ++c) {
      if (bodies[b].field == bodies[c].field) continue;
      contact.friction[static_cast<std::size_t>(bodies[b].field)]
                      [static_cast<std::size_t>(bodies[c].field)] =
          d.contact.friction_between(static_cast<int>(b), static_cast<int>(c));
    }
  }
  impulse_on_field.assign(static_cast<std::size_t>(field_count), Vec<Dim>::Zero());
  impulse_by_slab.assign(
      static_cast<std::size_t>(detail::ParticleBins::slab_of_row(grid.cells[Dim - 1] - 1) + 1) *
          static_cast<std::size_t>(field_count),
      Vec<Dim>::Zero());
  if (d.gimp_domain == GimpDomain::deformed) initial_half_length = particles.half_length;
  faces = detail::face_values(grid);
  if (d.thermal.enabled) {
    grid.allocate_heat();
    heat.emplace(d.thermal, std::move(body_conductivity), faces, grid);
  }
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (bodies[particles.body[p]].is_rigid())
      particles.velocity[p] = bodies[particles.body[p]].rigid_velocity;

  detail::initialise_geostatic_stress(description, bodies,
                                      gravity_at(std::max(d.gravity_ramp_time, 0.0)), particles);
  initial_strain_energy = totals().strain_energy;
  const Vec<Dim> upper = grid.upper();
  for (int k = 0; k < Dim; ++k) {
    const auto walled = [&](int face) {
      return d.boundaries[static_cast<std::size_t>(face)].kind != FaceCondition::Kind::free;
    };
    wall_lower[k] = walled(2 * k) ? grid.origin[k] : -std::numeric_limits<double>::infinity();
    wall_upper[k] = walled(2 * k + 1) ? upper[k] : std::numeric_limits<double>::infinity();
  }
}

template <int Dim>
void Solver<Dim>::Impl::allocate_grid(int field_count) {
  grid.allocate(field_count);
  odd_mass.assign(grid.mass.size(), 0.0);
  odd_momentum.assign(grid.momentum.size(), Vec<Dim>::Zero());
  odd_force.assign(grid.force.size(), Vec<Dim>::Zero());
  odd_mass_gradient.assign(grid.mass_gradient.size(), Vec<Dim>::Zero());
  odd_remapped.assign(grid.remapped_velocity.size(), Vec<Dim>::Zero());
  const int planes = grid.stored_planes == 0 ? grid.dofs[Dim - 1] : grid.stored_planes;
  slab_of_plane.resize(static_cast<std::size_t>(planes));
  for (int j = 0; j < planes; ++j)
    slab_of_plane[static_cast<std::size_t>(j)] = static_cast<std::size_t>(
        detail::ParticleBins::slab_of_row(grid.cell_row_of_plane(grid.first_plane + j)));
}

// Keeps the points of the partition's cell rows and the planes of grid
// values they touch (architecture.md §15).
template <int Dim>
void Solver<Dim>::Impl::restrict_to(std::shared_ptr<GridPartition<Dim>> part) {
  partition = std::move(part);
  const auto rows = partition->owned_rows();
  const auto owns = [&](int row) { return row >= rows[0] && row < rows[1]; };
  std::size_t kept = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (!owns(grid.cell_of(particles.position[p])[Dim - 1])) continue;
    if (kept != p) particles.for_each_array([&](auto& array) { array[kept] = array[p]; });
    ++kept;
  }
  particles.for_each_array([&](auto& array) { array.resize(kept); });
  store_planes_of_owned_rows();
}

// The planes of grid values the partition's rows own and their points touch.
template <int Dim>
void Solver<Dim>::Impl::store_planes_of_owned_rows() {
  const auto rows = partition->owned_rows();
  const auto owns = [&](int row) { return row >= rows[0] && row < rows[1]; };
  const int planes = grid.dofs[Dim - 1];
  PlaneRanges ranges;
  ranges.owned_first = planes;
  for (int j = 0; j < planes; ++j) {
    if (!owns(grid.cell_row_of_plane(j))) continue;
    ranges.owned_first = std::min(ranges.owned_first, j);
    ranges.owned_end = j + 1;
  }
  // The points of row r touch the planes r - 1 to r + 2 (GIMP; fewer for
  // the others).
  ranges.stored_first = std::min(ranges.owned_first, std::max(0, rows[0] - 1));
  ranges.stored_end = std::max(ranges.owned_end, std::min(planes, rows[1] + 2));
  grid.first_plane = ranges.stored_first;
  grid.stored_planes = ranges.stored_end - ranges.stored_first;
  grid.owned_first_plane = ranges.owned_first;
  grid.owned_planes = ranges.owned_end - ranges.owned_first;
  allocate_grid(grid.fields);
  faces = detail::face_values(grid);
  if (heat) {
    grid.allocate_heat();
    heat->attach(faces, grid, partition.get());
  }
  partition->set_planes(ranges, grid.plane_size(), grid.fields);
}

// The local index of the point with id `id` (a point of a surface load),
// or particles.size() when another rank holds it.
template <int Dim>
std::size_t Solver<Dim>::Impl::local_index(std::size_t id) const {
  if (!partition) return id;
  const auto at = std::lower_bound(particles.id.begin(), particles.id.end(), id);
  return at != particles.id.end() && *at == id ? static_cast<std::size_t>(at - particles.id.begin())
                                               : particles.size();
}

template <int Dim>
Vec<Dim> Solver<Dim>::Impl::gravity_at(double t) const {
  const double ramp =
      description.gravity_ramp_time > 0.0 ? std::min(1.0, t / description.gravity_ramp_time) : 1.0;
  return ramp * shrink<Dim>(description.gravity);
}

// One explicit step: Zheng et al., Algorithm 1 (MPM part) and eqs. 13-21,
// with the MUSL re-mapping and PIC/FLIP blend of Pan et al. 2021, eqs. 70-73.
template <int Dim>
void Solver<Dim>::Impl::step(double dt) {
  with_kernel<Dim>(description.shape, [&](auto kernel) {
    using Kernel = decltype(kernel);
    bin_particles();
    apply_surface_loads(dt);
    apply_coupling_forces(dt);
    add_external_work(dt);
    set_rigid_velocities(dt);
    interpolate_particles_to_grid<Kernel>(dt);
    if (heat) {
      apply_heat_sources(dt);
      interpolate_heat_to_grid<Kernel>();
      conduct_heat<Kernel>();
      integrate_grid_temperature(dt);
      interpolate_temperature_change_to_particles<Kernel>();
    }
    integrate_grid_momentum(dt);
    apply_grid_corrections(dt);
    apply_contact_and_boundaries(dt);
    if (description.scheme == UpdateScheme::usl) {
      interpolate_grid_to_particles<Kernel>(dt);
    } else {
      interpolate_and_remap_velocities<Kernel>();
      update_positions_and_stresses<Kernel>(dt);
    }
    if (description.gimp_domain == GimpDomain::deformed) update_particle_domains();
    move_rigid_bodies(dt);
    if (partition) partition->migrate(particles);
  });
  time += dt;
  ++steps;
}

template <int Dim>
void Solver<Dim>::Impl::bin_particles() {
  // A point gone non-finite since the last check_state() would index the bins
  // and the grid out of range: stop with the check's message instead.
  if (!std::all_of(particles.position.begin(), particles.position.end(),
                   [](const Vec<Dim>& x) { return x.allFinite(); }))
    check_state();
  bins.build(particles, grid);
}

template <int Dim>
void Solver<Dim>::Impl::apply_surface_loads(double /*dt*/) {
  std::fill(particles.external_force.begin(), particles.external_force.end(), Vec<Dim>::Zero());
  for (const LoadSpec& load : description.loads) {
    const double ramp = load.ramp_factor(time);
    const int axis = load.face / 2;
    const double outward = load.face % 2 == 0 ? -1.0 : 1.0;
    for (const std::size_t id : load.particles) {
      const std::size_t p = local_index(id);
      if (p == particles.size()) continue;  // held by another rank
      // Face area of the particle's initial domain normal to the face.
      const Vec<Dim>& l0 =
          initial_half_length.empty() ? particles.half_length[p] : initial_half_length[p];
      const double area = particles.initial_volume[p] / (2.0 * l0[axis]);
      Vec<Dim> force = Vec<Dim>::Zero();
      if (load.traction) force = shrink<Dim>(*load.traction) * area;
      if (load.pressure) force[axis] -= outward * *load.pressure * area;
      particles.external_force[p] += ramp * force;
    }
  }
}

// Where the coupling acts: the fluid's forces on the points, the pore
// pressure's -phi_s grad p (Tran et al., MPMICE, eq. 7) and the exchanged
// drag impulse over dt, added to the surface loads by the force sources.
template <int Dim>
void Solver<Dim>::Impl::apply_coupling_forces(double dt) {
  for (auto& source : force_sources) source(time, dt, particles);
}

// The work of the surface loads and the coupling forces over the step.
template <int Dim>
void Solver<Dim>::Impl::add_external_work(double dt) {
  if (description.loads.empty() && force_sources.empty()) return;  // no external force, no work
  double work = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    work += particles.external_force[p].dot(particles.velocity[p]) * dt;
  accumulated.external_work += work;
}

template <int Dim>
void Solver<Dim>::Impl::set_rigid_velocities(double dt) {
  for (auto& body : bodies) {
    if (!body.is_rigid()) continue;
    switch (body.rigid->kind) {
      case RigidMotion::Kind::fixed:
        body.rigid_velocity.setZero();
        break;
      case RigidMotion::Kind::prescribed:
        body.rigid_velocity = shrink<Dim>(body.rigid->velocity.at(time + dt));
        break;
      case RigidMotion::Kind::free:
        break;  // set by move_rigid_bodies from the last step's forces
    }
  }
  if (!has_rigid_body()) return;  // no pass over the points for nothing
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (body_of(p).is_rigid()) particles.velocity[p] = body_of(p).rigid_velocity;
}

// Zheng et al., eqs. 14-17: lumped mass, momentum, and the internal, body
// and external forces at the grid values. The internal force is the
// divergence of the effective stress; the pore fluid acts through the
// external force -phi_s grad p its coupling adds (Tran et al., MPMICE, eq. 7).
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::interpolate_particles_to_grid(double /*dt*/) {
  grid.clear();
  const Vec<Dim> g = gravity_at(time);
  const bool gradients = grid.fields > 1;
  bins.scatter([&](std::size_t p, int parity) {
    Stencil<Dim, Kernel> stencil;
    stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
    const std::size_t offset = stored(field_of(p), 0);  // + flat index: stored index
    const double m = particles.mass[p];
    const Vec<Dim> mv = m * particles.velocity[p];
    const Mat<Dim> volume_stress =
        particles.volume[p] * from_voigt(particles.stress[p]).template topLeftCorner<Dim, Dim>();
    const Vec<Dim> external = m * g + particles.external_force[p];
    double* mass = parity == 0 ? grid.mass.data() : odd_mass.data();
    Vec<Dim>* momentum = parity == 0 ? grid.momentum.data() : odd_momentum.data();
    Vec<Dim>* force = parity == 0 ? grid.force.data() : odd_force.data();
    Vec<Dim>* mass_gradient = parity == 0 ? grid.mass_gradient.data() : odd_mass_gradient.data();
    stencil.for_each([&](std::size_t v, double w, const Vec<Dim>& grad) {
      const std::size_t i = offset + v;
      mass[i] += w * m;
      momentum[i] += w * mv;
      force[i] += w * external - volume_stress * grad;
      if (gradients) mass_gradient[i] += m * grad;
    });
  });
  if (partition) {
    std::vector<GridArray> sums{array_of(grid.mass), array_of(grid.momentum), array_of(grid.force),
                                array_of(odd_mass),  array_of(odd_momentum),  array_of(odd_force)};
    if (gradients) {
      sums.push_back(array_of(grid.mass_gradient));
      sums.push_back(array_of(odd_mass_gradient));
    }
    partition->accumulate(sums);
  }
  const bool parallel = worth_threads(grid.mass.size());
  detail::add_odd_partials(grid.mass, odd_mass, parallel);
  detail::add_odd_partials(grid.momentum, odd_momentum, parallel);
  detail::add_odd_partials(grid.force, odd_force, parallel);
  if (gradients) detail::add_odd_partials(grid.mass_gradient, odd_mass_gradient, parallel);
}

// Zheng et al., eqs. 18-19: v^{n+1} = (p + dt f) / m, with optional local
// damping of the unbalanced force.
template <int Dim>
void Solver<Dim>::Impl::integrate_grid_momentum(double dt) {
  const std::size_t total = grid.mass.size();
  const std::size_t n = grid.size();
  const double damping = description.damping;
#pragma omp parallel for schedule(static) if (worth_threads(total))
  for (std::size_t i = 0; i < total; ++i) {
    const double m = grid.mass[i];
    if (m <= 1e-300) {
      grid.velocity[i].setZero();
      grid.velocity_change[i].setZero();
      continue;
    }
    const int field = static_cast<int>(i / n);
    const Vec<Dim> v_old = grid.momentum[i] / m;
    if (contact.rigid[static_cast<std::size_t>(field)]) {
      grid.velocity[i] = v_old;  // the rigid velocity itself (all its particles carry it)
      grid.velocity_change[i].setZero();
      continue;
    }
    Vec<Dim> force = grid.force[i];
    if (damping > 0.0) {
      for (int d = 0; d < Dim; ++d) {
        const double direction = v_old[d] + dt * force[d] / m;
        force[d] -= damping * std::abs(force[d]) *
                    (direction > 0   ? 1.0
                     : direction < 0 ? -1.0
                                     : 0.0);
      }
    }
    grid.velocity[i] = v_old + dt * force / m;
    grid.velocity_change[i] = v_old;  // holds v^n until contact and boundaries are applied
  }
}

template <int Dim>
void Solver<Dim>::Impl::apply_grid_corrections(double dt) {
  for (auto& correction : grid_corrections) correction(time, dt, grid);
}

template <int Dim>
void Solver<Dim>::Impl::apply_contact_and_boundaries(double /*dt*/) {
  if (grid.fields > 1) {
    const auto result = detail::apply_grid_contact(
        contact, grid, [&](std::size_t v) { return slab_of_value(v); }, impulse_by_slab);
    accumulated.contact_dissipation += result.dissipated;
    sum_contact_impulse();
    for (auto& body : bodies)
      if (body.is_rigid())
        body.contact_impulse = impulse_on_field[static_cast<std::size_t>(body.field)];
  }
  accumulated.boundary_dissipation +=
      detail::apply_face_conditions(description.boundaries, faces, contact.rigid, grid);
  const std::size_t total = grid.mass.size();
#pragma omp parallel for schedule(static) if (worth_threads(total))
  for (std::size_t i = 0; i < total; ++i) {
    if (grid.mass[i] <= 1e-300) continue;
    grid.velocity_change[i] = grid.velocity[i] - grid.velocity_change[i];  // v^{n+1} - v^n
  }
  if (partition) {
    const GridArray updated[] = {array_of(grid.velocity), array_of(grid.velocity_change)};
    partition->exchange(updated);
  }
}

// The reaction on each field summed slab by slab, in slab order, the slabs'
// sums first added over the ranks (each slab has one owner, so exactly).
template <int Dim>
void Solver<Dim>::Impl::sum_contact_impulse() {
  if (partition) partition->sum({impulse_by_slab.data()->data(), impulse_by_slab.size() * Dim});
  const std::size_t fields = impulse_on_field.size();
  for (std::size_t f = 0; f < fields; ++f) {
    Vec<Dim> total = Vec<Dim>::Zero();
    for (std::size_t slab = 0; slab * fields < impulse_by_slab.size(); ++slab)
      total += impulse_by_slab[slab * fields + f];
    impulse_on_field[f] = total;
  }
}

template <int Dim>
void Solver<Dim>::Impl::apply_heat_sources(double dt) {
  std::fill(particles.external_heat.begin(), particles.external_heat.end(), 0.0);
  if (heat_sources.empty()) return;
  for (auto& source : heat_sources) source(time, dt, particles);
  double heat_in = 0.0;
  for (const double q : particles.external_heat) heat_in += q * dt;
  accumulated.external_heat += heat_in;
}

// Tran et al., MPMICE, eq. 39: heat capacity and temperature of the grid.
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::interpolate_heat_to_grid() {
  heat->template interpolate_to_grid<Kernel>(particles, bins, geometry, grid);
}

// Tran et al., MPMICE, eq. 55: the conduction rate at the grid values.
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::conduct_heat() {
  heat->template conduct<Kernel>(particles, bins, geometry, grid);
}

// Tran et al., MPMICE, eq. 56, with the fixed-temperature faces.
template <int Dim>
void Solver<Dim>::Impl::integrate_grid_temperature(double dt) {
  accumulated.heat_through_faces += heat->integrate(dt, grid);
}

// Tran et al., MPMICE, eqs. 87 and 92.
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::interpolate_temperature_change_to_particles() {
  heat->template interpolate_to_particles<Kernel>(particles, bins, geometry, grid);
}

template <int Dim>
template <class Kernel>
Mat<Dim> Solver<Dim>::Impl::velocity_gradient(const Stencil<Dim, Kernel>& stencil,
                                              const std::vector<Vec<Dim>>& field_velocity,
                                              std::size_t offset) const {
  Mat<Dim> L = Mat<Dim>::Zero();
  stencil.for_each([&](std::size_t v, double /*w*/, const Vec<Dim>& grad) {
    L.noalias() += field_velocity[offset + v] * grad.transpose();
  });
  return L;
}

// USL: Zheng et al., eqs. 20-21 and Pan et al. 2021, eqs. 71-72, blended,
// v_p <- a (v_p + sum N dv) + (1 - a) sum N v^{n+1}, x_p <- x_p + dt sum N v^{n+1},
// then the kinematics and stresses from the same grid velocities.
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::interpolate_grid_to_particles(double dt) {
  update_kinematics_and_stress<Kernel>(dt, /*use_remapped=*/false);
}

// MUSL: the particle velocities updated with the same blend as USL;
// their momenta mapped back to the grid give the velocity the strain rate is
// computed from (Pan et al. 2021, Sec. 3.2). One stencil per point serves
// both: the update reads only the grid velocities, the re-map writes only
// the re-mapped ones.
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::interpolate_and_remap_velocities() {
  const double flip = description.flip_fraction;
  const std::size_t n = grid.size();
  std::fill(grid.remapped_velocity.begin(), grid.remapped_velocity.end(), Vec<Dim>::Zero());
  bins.scatter([&](std::size_t p, int parity) {
    if (body_of(p).is_rigid()) return;
    Stencil<Dim, Kernel> stencil;
    stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
    const std::size_t offset = stored(field_of(p), 0);
    Vec<Dim> v_pic = Vec<Dim>::Zero();
    Vec<Dim> dv = Vec<Dim>::Zero();
    stencil.for_each([&](std::size_t v, double w, const Vec<Dim>&) {
      v_pic += w * grid.velocity[offset + v];
      dv += w * grid.velocity_change[offset + v];
    });
    particles.velocity[p] = flip * (particles.velocity[p] + dv) + (1.0 - flip) * v_pic;
    const Vec<Dim> mv = particles.mass[p] * particles.velocity[p];
    Vec<Dim>* remapped = parity == 0 ? grid.remapped_velocity.data() : odd_remapped.data();
    stencil.for_each(
        [&](std::size_t v, double w, const Vec<Dim>&) { remapped[offset + v] += w * mv; });
  });
  const std::size_t total = grid.mass.size();
  if (partition) {
    const GridArray sums[] = {array_of(grid.remapped_velocity), array_of(odd_remapped)};
    partition->accumulate(sums);
  }
  detail::add_odd_partials(grid.remapped_velocity, odd_remapped, worth_threads(total));
#pragma omp parallel for schedule(static) if (worth_threads(total))
  for (std::size_t i = 0; i < total; ++i) {
    const int field = static_cast<int>(i / n);
    if (contact.rigid[static_cast<std::size_t>(field)]) {
      grid.remapped_velocity[i] = grid.velocity[i];
    } else {
      grid.remapped_velocity[i] = grid.mass[i] > 1e-300
                                      ? Vec<Dim>(grid.remapped_velocity[i] / grid.mass[i])
                                      : Vec<Dim>::Zero();
    }
  }
  // The re-mapped velocity obeys the same contact and face conditions.
  std::swap(grid.velocity, grid.remapped_velocity);
  if (grid.fields > 1) {
    std::vector<Vec<Dim>> unused(impulse_by_slab.size(), Vec<Dim>::Zero());
    detail::apply_grid_contact(
        contact, grid, [&](std::size_t v) { return slab_of_value(v); }, unused);
  }
  detail::apply_face_conditions(description.boundaries, faces, contact.rigid, grid);
  std::swap(grid.velocity, grid.remapped_velocity);
  if (partition) {
    const GridArray remapped[] = {array_of(grid.remapped_velocity)};
    partition->exchange(remapped);
  }
}

template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::update_positions_and_stresses(double dt) {
  update_kinematics_and_stress<Kernel>(dt, /*use_remapped=*/true);
}

// Positions (eq. 21), deformation gradient (Tran et al., MPMICE, eq. 94;
// Pan et al. 2021, eq. 73), volume and porosity (Pan et al. 2021, eqs.
// 74-76), then the stress from the material with its objective rate. USL
// also updates the particle velocities here (use_remapped = false).
template <int Dim>
template <class Kernel>
void Solver<Dim>::Impl::update_kinematics_and_stress(double dt, bool use_remapped) {
  const double flip = description.flip_fraction;
  const std::vector<Vec<Dim>>& strain_velocity =
      use_remapped ? grid.remapped_velocity : grid.velocity;
  const LockingMitigation locking = description.locking;
  const bool averaged = locking != LockingMitigation::none;
  const auto count = static_cast<std::ptrdiff_t>(particles.size());

  if (averaged) {
    // Cell-averaged volumetric increment: sum V x / sum V over the cell's points.
    cell_sum.assign(grid.cell_count(), 0.0);
    cell_weight.assign(grid.cell_count(), 0.0);
    volumetric_increment.resize(particles.size());
    bins.per_slab([&](std::size_t p) {
      if (body_of(p).is_rigid()) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      const Mat<Dim> L = velocity_gradient(stencil, strain_velocity, stored(field_of(p), 0));
      const double x = locking == LockingMitigation::fbar
                           ? (Mat<Dim>::Identity() + dt * L).determinant()
                           : dt * L.trace();
      volumetric_increment[p] = x;
      const std::size_t c = grid.cell_flat(grid.cell_of(particles.position[p]));
      cell_sum[c] += particles.volume[p] * x;
      cell_weight[c] += particles.volume[p];
    });
  }

  stress_work.assign(particles.size(), 0.0);
#pragma omp parallel for schedule(static) if (worth_threads(particles.size()))
  for (std::ptrdiff_t q = 0; q < count; ++q) {
    const auto p = static_cast<std::size_t>(q);
    const auto& body = body_of(p);
    if (body.is_rigid()) continue;
    Stencil<Dim, Kernel> stencil;
    stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
    const std::size_t offset = stored(body.field, 0);
    Vec<Dim> v_pic = Vec<Dim>::Zero();
    Vec<Dim> dv = Vec<Dim>::Zero();
    Mat<Dim> L = Mat<Dim>::Zero();
    stencil.for_each([&](std::size_t v, double w, const Vec<Dim>& grad) {
      v_pic += w * grid.velocity[offset + v];
      if (!use_remapped) dv += w * grid.velocity_change[offset + v];
      L.noalias() += strain_velocity[offset + v] * grad.transpose();
    });
    if (!use_remapped)
      particles.velocity[p] = flip * (particles.velocity[p] + dv) + (1.0 - flip) * v_pic;
    const std::size_t cell = averaged ? grid.cell_flat(grid.cell_of(particles.position[p])) : 0;
    particles.position[p] =
        (particles.position[p] + dt * v_pic).cwiseMax(wall_lower).cwiseMin(wall_upper);

    detail::VolumetricAverage average;
    if (averaged && cell_weight[cell] > 0.0) {
      average.kind = locking;
      average.own = volumetric_increment[p];
      average.cell = cell_sum[cell] / cell_weight[cell];
    }
    stress_work[p] = detail::update_point(
        *body.material, L, dt, average, description.bodies[particles.body[p]].porous, p, particles);
  }
  // Summed in particle order, not by a reduction: the same bits whatever the
  // thread count, and from one run to the next.
  double work = 0.0;
  for (const double w : stress_work) work += w;
  accumulated.internal_work += work;
}

// cpGIMP (Bardenhagen and Kober 2004): the domain stays aligned with the
// axes and stretches with the diagonal of F, l_p,i = l_p0,i |F_ii|. Of the
// axis-aligned choices this one keeps prod_i l_p,i = J prod_i l_p0,i for
// stretches along the axes and leaves the domain alone under simple shear;
// the lengths of the convected edge vectors F l_p0,i e_i (Sadeghirad et al.
// 2011), the other common choice, grow with shear and overlap neighbours.
template <int Dim>
void Solver<Dim>::Impl::update_particle_domains() {
  const auto count = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp parallel for schedule(static) if (worth_threads(particles.size()))
  for (std::ptrdiff_t q = 0; q < count; ++q) {
    const auto p = static_cast<std::size_t>(q);
    if (body_of(p).is_rigid()) continue;
    particles.half_length[p] = initial_half_length[p].cwiseProduct(
        particles.deformation_gradient[p].diagonal().cwiseAbs());
  }
}

template <int Dim>
void Solver<Dim>::Impl::move_rigid_bodies(double dt) {
  const Vec<Dim> g = gravity_at(time);
  for (auto& body : bodies) {
    if (!body.is_rigid()) continue;
    if (body.rigid->kind == RigidMotion::Kind::free && body.mass > 0.0)
      body.rigid_velocity += dt * g + body.contact_impulse / body.mass;
  }
  if (!has_rigid_body()) return;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    if (!body_of(p).is_rigid()) continue;
    particles.position[p] += dt * particles.velocity[p];
    particles.velocity[p] = body_of(p).rigid_velocity;
  }
}

template <int Dim>
double Solver<Dim>::Impl::stable_time_step() const {
  double wave = 0.0;
  double speed = 0.0;
  const auto count = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp parallel for schedule(static) \
    reduction(max                         \
              : wave, speed) if (worth_threads(particles.size()))
  for (std::ptrdiff_t q = 0; q < count; ++q) {
    const auto p = static_cast<std::size_t>(q);
    const auto& body = body_of(p);
    speed = std::max(speed, particles.velocity[p].cwiseAbs().maxCoeff());
    if (body.is_rigid() || particles.volume[p] <= 0.0) continue;
    const double density = particles.mass[p] / particles.volume[p];
    if (density > 0.0) wave = std::max(wave, std::sqrt(body.p_wave_modulus / density));
  }
  if (partition) {
    wave = partition->max(wave);
    speed = partition->max(speed);
  }
  // Zheng et al., eq. 23.
  const double denominator = wave + speed;
  double dt = denominator > 0.0 ? description.time.safety_factor * grid.min_spacing() / denominator
                                : description.time.max_time_step;
  if (heat)
    dt = std::min(
        dt, heat->stable_time_step(particles, grid.min_spacing(), description.time.safety_factor));
  return std::min(dt, description.time.max_time_step);
}

template <int Dim>
Totals<Dim> Solver<Dim>::Impl::totals() const {
  Totals<Dim> t;
  const Vec<Dim> g = gravity_at(time);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double m = particles.mass[p];
    t.mass += m;
    t.momentum += m * particles.velocity[p];
    t.kinetic_energy += 0.5 * m * particles.velocity[p].squaredNorm();
    t.gravitational_energy -= m * g.dot(particles.position[p]);
    const auto& body = body_of(p);
    if (!body.is_rigid()) {
      // Complementary elastic energy V (p^2 / 2K + s:s / 4G) of the current stress.
      const Tensor s = from_voigt(particles.stress[p]);
      const double mean = s.trace() / 3.0;
      const Tensor dev = s - mean * Tensor::Identity();
      t.strain_energy +=
          particles.volume[p] * (mean * mean / (2.0 * body.material->bulk_modulus()) +
                                 dev.squaredNorm() / (4.0 * body.material->shear_modulus()));
    }
  }
  t.contact_dissipation = accumulated.contact_dissipation;
  t.boundary_dissipation = accumulated.boundary_dissipation;
  t.external_work = accumulated.external_work;
  t.internal_work = accumulated.internal_work;
  if (heat) {
    for (std::size_t p = 0; p < particles.size(); ++p)
      t.thermal_energy += particles.heat_capacity[p] * particles.temperature[p];
    t.external_heat = accumulated.external_heat;
    t.heat_through_faces = accumulated.heat_through_faces;
  }
  if (partition) {
    std::vector<double> sums{t.mass,
                             t.kinetic_energy,
                             t.strain_energy,
                             t.gravitational_energy,
                             t.contact_dissipation,
                             t.boundary_dissipation,
                             t.external_work,
                             t.internal_work};
    for (int d = 0; d < Dim; ++d) sums.push_back(t.momentum[d]);
    sums.insert(sums.end(), {t.thermal_energy, t.external_heat, t.heat_through_faces});
    partition->sum(sums);
    t.thermal_energy = sums[8 + Dim];
    t.external_heat = sums[9 + Dim];
    t.heat_through_faces = sums[10 + Dim];
    t.mass = sums[0];
    t.kinetic_energy = sums[1];
    t.strain_energy = sums[2];
    t.gravitational_energy = sums[3];
    t.contact_dissipation = sums[4];
    t.boundary_dissipation = sums[5];
    t.external_work = sums[6];
    t.internal_work = sums[7];
    for (int d = 0; d < Dim; ++d) t.momentum[d] = sums[8 + static_cast<std::size_t>(d)];
  }
  t.plastic_dissipation = t.internal_work - (t.strain_energy - initial_strain_energy);
  return t;
}

template <int Dim>
void Solver<Dim>::Impl::check_state() const {
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const auto& body = body_of(p);
    const Voigt& s = particles.stress[p];
    const bool finite =
        particles.position[p].allFinite() && particles.velocity[p].allFinite() &&
        std::all_of(s.begin(), s.end(), [](double x) { return std::isfinite(x); }) &&
        std::isfinite(particles.volume[p]) && particles.volume[p] > 0.0 &&
        std::isfinite(particles.temperature[p]);
    if (!finite) {
      throw cosim::NumericalError(fmt::format(
          "particle {} of body '{}' has a non-finite or collapsed state at t = {:.9g} s "
          "(position {}, volume {:.6g} m^{}, temperature {:.6g} K)",
          particles.id[p], body.name, time, fmt::join(particles.position[p], ", "),
          particles.volume[p], Dim, particles.temperature[p]));
    }
    if (!grid.contains(particles.position[p])) {
      throw cosim::NumericalError(
          fmt::format("particle {} of body '{}' left the grid at t = {:.9g} s (position {}; grid "
                      "from {} to {})",
                      particles.id[p], body.name, time, fmt::join(particles.position[p], ", "),
                      fmt::join(grid.origin, ", "), fmt::join(grid.upper(), ", ")));
    }
  }
}

// Public interface.

template <int Dim>
Solver<Dim>::Solver(const CaseDescription& description)
    : impl_(std::make_unique<Impl>(description)) {}
template <int Dim>
Solver<Dim>::Solver(const CaseDescription& description,
                    std::shared_ptr<GridPartition<Dim>> partition)
    : impl_(std::make_unique<Impl>(description)) {
  if (partition) impl_->restrict_to(std::move(partition));
}
template <int Dim>
Solver<Dim>::~Solver() = default;
template <int Dim>
double Solver<Dim>::stable_time_step() const {
  return impl_->stable_time_step();
}
template <int Dim>
void Solver<Dim>::step(double dt) {
  impl_->step(dt);
}
template <int Dim>
void Solver<Dim>::repartition() {
  Impl& s = *impl_;
  if (!s.partition) return;
  s.store_planes_of_owned_rows();
  s.partition->migrate(s.particles);
}
template <int Dim>
GridPartition<Dim>* Solver<Dim>::partition() const {
  return impl_->partition.get();
}
template <int Dim>
double Solver<Dim>::time() const {
  return impl_->time;
}
template <int Dim>
std::size_t Solver<Dim>::step_count() const {
  return impl_->steps;
}
template <int Dim>
void Solver<Dim>::save(SolverState<Dim>& state) const {
  const Impl& s = *impl_;
  state.particles_ = s.particles;
  state.rigid_velocity_.resize(s.bodies.size());
  state.contact_impulse_.resize(s.bodies.size());
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    state.rigid_velocity_[b] = s.bodies[b].rigid_velocity;
    state.contact_impulse_[b] = s.bodies[b].contact_impulse;
  }
  state.time_ = s.time;
  state.steps_ = s.steps;
  state.accumulated_ = s.accumulated;
  state.saved_ = true;
}
template <int Dim>
void Solver<Dim>::restore(const SolverState<Dim>& state) {
  Impl& s = *impl_;
  // On a rank the points held change with migration; every rank restores
  // the same step together.
  if (!state.saved_ || (!s.partition && state.particles_.size() != s.particles.size()) ||
      state.rigid_velocity_.size() != s.bodies.size())
    throw cosim::Error(cosim::ExitCode::internal_error,
                       "restoring a solver state that was not saved from this solver");
  s.particles = state.particles_;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    s.bodies[b].rigid_velocity = state.rigid_velocity_[b];
    s.bodies[b].contact_impulse = state.contact_impulse_[b];
  }
  s.time = state.time_;
  s.steps = state.steps_;
  s.accumulated = state.accumulated_;
}
template <int Dim>
void Solver<Dim>::write_state(cosim::StateFileWriter& out) const {
  const Impl& s = *impl_;
  write_particles(out, s.particles);
  std::vector<Vec<Dim>> rigid_velocity, contact_impulse;
  for (const auto& body : s.bodies) {
    rigid_velocity.push_back(body.rigid_velocity);
    contact_impulse.push_back(body.contact_impulse);
  }
  out.rows("bodies.rigid_velocity", rigid_velocity);
  out.rows("bodies.contact_impulse", contact_impulse);
  out.number("time", s.time);
  out.integer("steps", static_cast<std::int64_t>(s.steps));
  const AccumulatedEnergy& e = s.accumulated;
  out.numbers("accumulated_energy",
              std::array{e.contact_dissipation, e.boundary_dissipation, e.external_work,
                         e.internal_work, e.external_heat, e.heat_through_faces});
}
template <int Dim>
void Solver<Dim>::read_state(const cosim::StateFileReader& in) {
  const cosim::StateFileReader* const parts[] = {&in};
  read_state(parts, 0, 1);
}
template <int Dim>
void Solver<Dim>::read_state(std::span<const cosim::StateFileReader* const> parts, int rank,
                             int ranks) {
  Impl& s = *impl_;
  std::vector<const cosim::StateFileReader*> mine;
  for (auto p = static_cast<std::size_t>(rank); p < parts.size();
       p += static_cast<std::size_t>(ranks))
    mine.push_back(parts[p]);
  read_particles(std::span<const cosim::StateFileReader* const>(mine), s.particles);
  std::size_t seeded = 0;
  for (const auto& body : s.description.bodies) seeded += body.positions.size();
  double points = static_cast<double>(s.particles.size());
  if (s.partition) s.partition->sum({&points, 1});
  if (points != static_cast<double>(seeded))
    throw cosim::InputError(
        fmt::format("{} and the other parts of its checkpoint hold {} points, "
                    "the case seeds {}",
                    parts[0]->file().string(), points, seeded));
  if (s.partition) s.partition->migrate(s.particles);
  std::array<double, 6> energy{};
  for (const auto* in : mine) {
    std::vector<double> e;
    in->numbers("accumulated_energy", 6, e);
    for (std::size_t k = 0; k < energy.size(); ++k) energy[k] += e[k];
  }
  s.accumulated = {energy[0], energy[1], energy[2], energy[3], energy[4], energy[5]};
  const cosim::StateFileReader& first = *parts[0];
  std::vector<Vec<Dim>> rigid_velocity, contact_impulse;
  first.rows("bodies.rigid_velocity", s.bodies.size(), rigid_velocity);
  first.rows("bodies.contact_impulse", s.bodies.size(), contact_impulse);
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    s.bodies[b].rigid_velocity = rigid_velocity[b];
    s.bodies[b].contact_impulse = contact_impulse[b];
  }
  s.time = first.number("time");
  s.steps = static_cast<std::size_t>(first.integer("steps"));
}
template <int Dim>
void Solver<Dim>::add_particle_force_source(ParticleForceSource source) {
  impl_->force_sources.push_back(std::move(source));
}
template <int Dim>
void Solver<Dim>::add_grid_velocity_correction(GridVelocityCorrection correction) {
  impl_->grid_corrections.push_back(std::move(correction));
}
template <int Dim>
void Solver<Dim>::add_particle_heat_source(ParticleHeatSource source) {
  impl_->heat_sources.push_back(std::move(source));
}
template <int Dim>
bool Solver<Dim>::conducts_heat() const {
  return impl_->heat.has_value();
}
template <int Dim>
Particles<Dim>& Solver<Dim>::particles() {
  return impl_->particles;
}
template <int Dim>
const Particles<Dim>& Solver<Dim>::particles() const {
  return impl_->particles;
}
template <int Dim>
std::size_t Solver<Dim>::local_index(std::size_t id) const {
  return impl_->local_index(id);
}
template <int Dim>
const Grid<Dim>& Solver<Dim>::grid() const {
  return impl_->grid;
}
template <int Dim>
const CaseDescription& Solver<Dim>::description() const {
  return impl_->description;
}
template <int Dim>
Totals<Dim> Solver<Dim>::totals() const {
  return impl_->totals();
}
template <int Dim>
Tensor Solver<Dim>::total_stress(std::size_t particle) const {
  return from_voigt(impl_->particles.stress[particle]) -
         impl_->particles.pore_pressure[particle] * Tensor::Identity();
}
template <int Dim>
void Solver<Dim>::check_state() const {
  impl_->check_state();
}

template class Solver<2>;
template class Solver<3>;

}  // namespace mpm

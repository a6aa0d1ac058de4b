#include "mpm/depth_averaged/depth_averaged_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cosim/error.hpp"
#include "mpm/shape/quadratic_bspline_kernel.hpp"
#include "mpm/shape/stencil.hpp"

namespace mpm {

namespace {

using Kernel = QuadraticBsplineKernel;
using GroundStencil = Stencil<2, Kernel>;

GroundStencil stencil_at(const Vec<2>& x, const GridGeometry<2>& grid) {
  GroundStencil s;
  s.evaluate(x, Vec<2>::Zero(), grid);
  return s;
}

bool inside(const Vec<2>& x, const GridGeometry<2>& grid) {
  const Vec<2> upper = grid.upper();
  return x[0] >= grid.origin[0] && x[0] <= upper[0] && x[1] >= grid.origin[1] && x[1] <= upper[1];
}

}  // namespace

DepthAveragedSolver::DepthAveragedSolver(DepthAveragedSettings settings,
                                         std::vector<DepthAveragedMaterial> materials,
                                         DepthAveragedParticles particles)
    : settings_(std::move(settings)),
      materials_(std::move(materials)),
      particles_(std::move(particles)) {
  const auto& grid = settings_.grid;
  for (int d = 0; d < 2; ++d) {
    if (grid.cells[d] < 2)
      throw std::invalid_argument("the ground grid needs at least 2 cells in each direction");
    if (!(grid.spacing[d] > 0.0))
      throw std::invalid_argument("the ground grid's spacing must be positive");
    nodes_[d] = Kernel::dofs(grid.cells[d]);
  }
  if (!(settings_.flip_fraction >= 0.0 && settings_.flip_fraction <= 1.0))
    throw std::invalid_argument("flip_fraction must be in [0, 1]");
  if (!(settings_.courant > 0.0 && settings_.courant <= 1.0))
    throw std::invalid_argument("courant must be in (0, 1]");
  if (materials_.empty()) throw std::invalid_argument("no material");
  for (const auto& m : materials_) m.check();
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const int m = particles_.material[p];
    if (m < 0 || m >= static_cast<int>(materials_.size()))
      throw std::invalid_argument(fmt::format("point {} has no material {}", p, m));
    if (!inside(particles_.position[p], grid))
      throw std::invalid_argument(fmt::format("point {} at ({}, {}) is outside the grid", p,
                                              particles_.position[p][0],
                                              particles_.position[p][1]));
    if (!(particles_.volume[p] > 0.0) || !(particles_.area[p] > 0.0))
      throw std::invalid_argument(fmt::format("point {} has no volume or no area", p));
  }
  const std::size_t n = static_cast<std::size_t>(nodes_[0]) * static_cast<std::size_t>(nodes_[1]);
  area_.assign(n, 0.0);
  mass_.assign(n, 0.0);
  momentum_.assign(n, Vec<2>::Zero());
  new_momentum_.assign(n, Vec<2>::Zero());
  force_.assign(n, Vec<2>::Zero());
  volume_.assign(n, 0.0);
  depth_.assign(n, 0.0);
  friction_.assign(n, 0.0);
  stopped_.assign(n, 0);
  for (const auto& o : settings_.obstacles) {
    if (!(o.max[0] > o.min[0] && o.max[1] > o.min[1]))
      throw std::invalid_argument("an obstacle's max must lie above its min");
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<2> x = node_position(i);
      if (x[0] >= o.min[0] && x[0] <= o.max[0] && x[1] >= o.min[1] && x[1] <= o.max[1])
        held_.push_back(i);
    }
  }
  if (!(settings_.confined_fluid_density > 0.0))
    throw std::invalid_argument("the confined fluid's density must be positive");
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
    particles_.structured_share[p] = m.structured_share;
    particles_.confined_fluid[p] =
        m.structured_share > 0.0 ? m.confined_fluid_fraction * particles_.volume[p] : 0.0;
    if (particles_.confined_fluid[p] > 0.0 &&
        !(particles_.density(p) > settings_.confined_fluid_density))
      throw std::invalid_argument(fmt::format(
          "material '{}' confines fluid of density {} kg/m^3 but is no denser itself ({} kg/m^3)",
          m.name, settings_.confined_fluid_density, particles_.density(p)));
  }
  if (settings_.still_water) {
    if (!(settings_.still_water->density > 0.0) || !std::isfinite(settings_.still_water->level))
      throw std::invalid_argument("still water needs a positive density and a finite level");
    std::vector<double> surface(n);
    for (std::size_t i = 0; i < n; ++i)
      surface[i] =
          settings_.terrain.height_of_level(settings_.still_water->level, node_position(i));
    set_fluid_surface(settings_.still_water->density, std::move(surface));
  }
  compute_node_areas();
  clear_grid();
  transfer_points_to_grid();
  compute_depth();
  new_momentum_ = momentum_;
}

// a_i = integral of N_i over the grid, by two-point Gauss quadrature per
// direction (exact for the piecewise quadratic N_i).
void DepthAveragedSolver::compute_node_areas() {
  const auto& grid = settings_.grid;
  const double g = 0.5 / std::sqrt(3.0);
  const double weight = 0.25 * grid.cell_volume();
  for (int cy = 0; cy < grid.cells[1]; ++cy)
    for (int cx = 0; cx < grid.cells[0]; ++cx)
      for (double qy : {0.5 - g, 0.5 + g})
        for (double qx : {0.5 - g, 0.5 + g}) {
          const Vec<2> x{grid.origin[0] + (cx + qx) * grid.spacing[0],
                         grid.origin[1] + (cy + qy) * grid.spacing[1]};
          stencil_at(x, grid).for_each(
              [&](std::size_t i, double N, const Vec<2>&) { area_[i] += N * weight; });
        }
}

Vec<2> DepthAveragedSolver::node_position(std::size_t node) const {
  const auto& grid = settings_.grid;
  const int i = static_cast<int>(node % static_cast<std::size_t>(nodes_[0]));
  const int j = static_cast<int>(node / static_cast<std::size_t>(nodes_[0]));
  return {grid.origin[0] + Kernel::dof_coordinate(i, grid.cells[0]) * grid.spacing[0],
          grid.origin[1] + Kernel::dof_coordinate(j, grid.cells[1]) * grid.spacing[1]};
}

double DepthAveragedSolver::depth_at(const Vec<2>& x) const {
  double h = 0.0;
  stencil_at(x, settings_.grid).for_each([&](std::size_t i, double N, const Vec<2>&) {
    h += N * depth_[i];
  });
  return h;
}

void DepthAveragedSolver::set_fluid_surface(double density, std::vector<double> surface_at_nodes) {
  if (surface_at_nodes.empty()) {
    fluid_surface_.clear();
    fluid_density_ = 0.0;
    return;
  }
  if (surface_at_nodes.size() != mass_.size())
    throw std::invalid_argument(fmt::format("the fluid surface has {} values for {} grid nodes",
                                            surface_at_nodes.size(), mass_.size()));
  if (!(density > 0.0) || !std::isfinite(density))
    throw std::invalid_argument(fmt::format("the fluid's density {} must be positive", density));
  for (std::size_t i = 0; i < surface_at_nodes.size(); ++i)
    if (!std::isfinite(surface_at_nodes[i]))
      throw std::invalid_argument(
          fmt::format("the fluid surface at node {} is {}", i, surface_at_nodes[i]));
  fluid_density_ = density;
  fluid_surface_ = std::move(surface_at_nodes);
}

double DepthAveragedSolver::fluid_surface_at(const Vec<2>& x) const {
  if (fluid_surface_.empty()) return -std::numeric_limits<double>::infinity();
  double eta = 0.0;
  stencil_at(x, settings_.grid).for_each([&](std::size_t i, double N, const Vec<2>&) {
    eta += N * fluid_surface_[i];
  });
  return eta;
}

DepthAveragedSolver::Submersion DepthAveragedSolver::submersion(std::size_t p) const {
  if (fluid_surface_.empty()) return {};
  return submersion_below(p, fluid_surface_at(particles_.position[p]));
}

DepthAveragedSolver::Submersion DepthAveragedSolver::submersion_below(std::size_t p,
                                                                      double surface) const {
  const Vec<2>& x = particles_.position[p];
  const double above_bed = surface - settings_.terrain.bed_elevation(x);
  const double s = std::clamp(above_bed, 0.0, particles_.depth(p));
  const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
  const double f_sc = particles_.structured_share[p];
  const double propagated = (1.0 - f_sc) + f_sc * m.basal_pressure_factor;  // eq. 39
  return {s, propagated * fluid_density_ * s};
}

Vec<2> DepthAveragedSolver::velocity_at(const Vec<2>& x) const {
  Vec<2> momentum = Vec<2>::Zero();
  double mass = 0.0;
  stencil_at(x, settings_.grid).for_each([&](std::size_t i, double N, const Vec<2>&) {
    momentum += N * new_momentum_[i];
    mass += N * mass_[i];
  });
  return mass > 0.0 ? Vec<2>(momentum / mass) : Vec<2>::Zero();
}

double DepthAveragedSolver::cohesion(std::size_t p) const {
  return materials_[static_cast<std::size_t>(particles_.material[p])].cohesion *
         (1.0 - particles_.damage[p]);
}

double DepthAveragedSolver::earth_pressure_coefficient(std::size_t p) const {
  const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
  return settings_.earth_pressure.coefficient(m.internal_friction_angle,
                                              particles_.areal_strain_rate[p]);
}

// The column's effective unit weight g cos(theta) (rho h - B_eff rho_f s) / h.
double DepthAveragedSolver::unit_weight(std::size_t p, double relieved_density_depth) const {
  const double h = particles_.depth(p);
  return settings_.terrain.normal_gravity() *
         std::max(0.0, particles_.density(p) - relieved_density_depth / h);
}

double DepthAveragedSolver::stable_time_step() const {
  const double g_n = settings_.terrain.normal_gravity();
  double fastest = 0.0;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
    // The wave speed with the larger of K's two values, as K may switch within the step.
    const double K =
        std::max(settings_.earth_pressure.coefficient(m.internal_friction_angle, 1.0),
                 settings_.earth_pressure.coefficient(m.internal_friction_angle, -1.0));
    const double wave = std::max(std::sqrt(K * g_n * particles_.depth(p)),
                                 m.in_plane.wave_speed(particles_.density(p)));
    fastest = std::max(fastest, particles_.velocity[p].norm() + wave);
  }
  if (fastest == 0.0) return std::numeric_limits<double>::infinity();
  return settings_.courant * settings_.grid.spacing.minCoeff() / fastest;
}

void DepthAveragedSolver::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument(fmt::format("a step must be positive and finite, not {}", dt));
  clear_grid();
  transfer_points_to_grid();
  compute_depth();
  add_internal_forces();
  advance_grid_momentum(dt);
  apply_walls();  // first: the walls' reaction to the thrust is no motion for friction to resist
  apply_basal_friction(dt);
  transfer_grid_to_points(dt);
  update_in_plane_stress(dt);
  degrade_cohesion(dt);
  split_stretched_points();
  time_ += dt;
}

long DepthAveragedSolver::advance_to(double end_time) {
  long steps = 0;
  while (time_ < end_time * (1.0 - 1e-14)) {
    double dt = std::min(stable_time_step(), end_time - time_);
    if (!std::isfinite(dt)) dt = end_time - time_;
    step(dt);
    ++steps;
  }
  return steps;
}

void DepthAveragedSolver::clear_grid() {
  std::fill(mass_.begin(), mass_.end(), 0.0);
  std::fill(momentum_.begin(), momentum_.end(), Vec<2>::Zero());
  std::fill(force_.begin(), force_.end(), Vec<2>::Zero());
  std::fill(volume_.begin(), volume_.end(), 0.0);
  std::fill(friction_.begin(), friction_.end(), 0.0);
}

void DepthAveragedSolver::transfer_points_to_grid() {
  const auto& terrain = settings_.terrain;
  const double g_n = terrain.normal_gravity();
  relieved_.resize(particles_.size());
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
    const double mp = particles_.mass[p];
    const GroundStencil stencil = stencil_at(particles_.position[p], settings_.grid);
    Vec<2> drive = mp * terrain.driving_acceleration(particles_.position[p]);
    double bearing_mass = mp;
    relieved_[p] = 0.0;
    if (!fluid_surface_.empty()) {
      double surface = 0.0;
      Vec<2> surface_slope = Vec<2>::Zero();
      stencil.for_each([&](std::size_t i, double N, const Vec<2>& dN) {
        surface += N * fluid_surface_[i];
        surface_slope += fluid_surface_[i] * dN;
      });
      const Submersion submerged = submersion_below(p, surface);
      relieved_[p] = submerged.relieved_density_depth;
      // eq. 54: the fluid's hydrostatic pressure gradient on the submerged
      // part, and its buoyancy, which the bed's slope turns along the ground
      // as it does the weight: -rho_f g s grad(eta - b).
      drive -= fluid_density_ * g_n * particles_.area[p] * submerged.depth *
               (surface_slope - terrain.bed_slope(particles_.position[p]));
      bearing_mass = std::max(0.0, mp - particles_.area[p] * submerged.relieved_density_depth);
    }
    const double capacity = bearing_mass * g_n * std::tan(m.basal_friction_angle);
    stencil.for_each([&](std::size_t i, double N, const Vec<2>&) {
      mass_[i] += N * mp;
      momentum_[i] += N * mp * particles_.velocity[p];
      volume_[i] += N * particles_.volume[p];
      force_[i] += N * drive;
      friction_[i] += N * capacity;
    });
  }
}

void DepthAveragedSolver::compute_depth() {
  for (std::size_t i = 0; i < depth_.size(); ++i) depth_[i] = volume_[i] / area_[i];
}

double DepthAveragedSolver::lateral_thrust(std::size_t p) const {
  return EarthPressure::thrust(earth_pressure_coefficient(p), unit_weight(p, relieved_[p]),
                               cohesion(p), particles_.depth(p));
}

// f_i = sum_p (A_p T(h_p) I - V_p sigma_p) grad N_ip: the weak form of
// -grad T + div(h sigma).
void DepthAveragedSolver::add_internal_forces() {
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const Mat<2> stress = particles_.area[p] * lateral_thrust(p) * Mat<2>::Identity() -
                          particles_.volume[p] * particles_.stress[p];
    if (stress.isZero(0.0)) continue;
    stencil_at(particles_.position[p], settings_.grid)
        .for_each([&](std::size_t i, double, const Vec<2>& dN) { force_[i] += stress * dN; });
  }
}

// The in-plane stress's elastic step, then Mohr-Coulomb on it with the
// earth pressure's mean stress -T/h, with the cohesion the point has left.
void DepthAveragedSolver::update_in_plane_stress(double dt) {
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
    if (!m.in_plane.enabled()) continue;
    const Mat<2> trial =
        m.in_plane.elastic_update(particles_.stress[p], particles_.velocity_gradient[p], dt);
    const Mat<2> earth = (lateral_thrust(p) / particles_.depth(p)) * Mat<2>::Identity();
    bool yielded = false;
    particles_.stress[p] =
        InPlaneStress::bounded(trial - earth, cohesion(p), m.internal_friction_angle, yielded) +
        earth;
    particles_.yielded[p] = yielded;
  }
}

void DepthAveragedSolver::advance_grid_momentum(double dt) {
  for (std::size_t i = 0; i < mass_.size(); ++i) new_momentum_[i] = momentum_[i] + dt * force_[i];
}

// Coulomb friction on the bed (eq. 36), |impulse| <= dt tan(delta) N: it
// opposes the motion the other forces would give and, where it could do more
// than stop the node, stops it.
void DepthAveragedSolver::apply_basal_friction(double dt) {
  for (std::size_t i = 0; i < mass_.size(); ++i) {
    const double largest = dt * friction_[i];
    const double speed_momentum = new_momentum_[i].norm();
    stopped_[i] = speed_momentum <= largest;
    if (stopped_[i])
      new_momentum_[i].setZero();
    else
      new_momentum_[i] *= 1.0 - largest / speed_momentum;
  }
}

void DepthAveragedSolver::apply_walls() {
  for (const std::size_t i : held_) new_momentum_[i].setZero();
  for (int d = 0; d < 2; ++d) {
    const int other = 1 - d;
    for (int side = 0; side < 2; ++side) {
      const GroundWall wall = settings_.walls[static_cast<std::size_t>(2 * d + side)];
      const int layer = side == 0 ? 0 : nodes_[d] - 1;
      for (int k = 0; k < nodes_[other]; ++k) {
        const int ix = d == 0 ? layer : k, iy = d == 0 ? k : layer;
        const std::size_t i = static_cast<std::size_t>(iy) * static_cast<std::size_t>(nodes_[0]) +
                              static_cast<std::size_t>(ix);
        if (wall == GroundWall::stick)
          new_momentum_[i].setZero();
        else
          new_momentum_[i][d] = 0.0;
      }
    }
  }
}

void DepthAveragedSolver::transfer_grid_to_points(double dt) {
  const double flip = settings_.flip_fraction;
  const auto& grid = settings_.grid;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    Vec<2> v_new = Vec<2>::Zero(), dv = Vec<2>::Zero();
    Mat<2> gradient = Mat<2>::Zero();  // L = grad v
    bool all_stopped = true;
    stencil_at(particles_.position[p], grid)
        .for_each([&](std::size_t i, double N, const Vec<2>& dN) {
          // Every node with mass takes part, however little: a quadratic
          // B-spline's weight N and slope (~sqrt(2 N)) vanish together, so a
          // light node's large velocity enters the point only as N v and
          // v grad N, both bounded, and leaving it out would lose momentum.
          if (mass_[i] <= 0.0) return;
          all_stopped = all_stopped && stopped_[i];
          const Vec<2> vi_new = new_momentum_[i] / mass_[i];
          v_new += N * vi_new;
          dv += N * (vi_new - momentum_[i] / mass_[i]);
          gradient += vi_new * dN.transpose();
        });
    // A point whose every node friction stopped is at rest, whatever FLIP
    // would carry over from its earlier velocity.
    particles_.velocity[p] =
        all_stopped ? Vec<2>::Zero()
                    : Vec<2>(flip * (particles_.velocity[p] + dv) + (1.0 - flip) * v_new);
    particles_.position[p] += dt * v_new;
    particles_.areal_strain_rate[p] = gradient.trace();
    particles_.velocity_gradient[p] = gradient;
    const Mat<2> increment = Mat<2>::Identity() + dt * gradient;
    const double stretch = increment.determinant();
    if (!(stretch > 0.0))
      throw cosim::NumericalError(fmt::format(
          "depth-averaged point {} was turned inside out at t = {} s (area ratio {}): the step is "
          "too long",
          p, time_ + dt, stretch));
    particles_.area[p] *= stretch;
    particles_.edges[p] = increment * particles_.edges[p];
    if (!particles_.velocity[p].allFinite() || !particles_.position[p].allFinite())
      throw cosim::NumericalError(
          fmt::format("depth-averaged point {} turned non-finite at t = {} s", p, time_ + dt));
    if (!inside(particles_.position[p], grid))
      throw cosim::NumericalError(fmt::format(
          "depth-averaged point {} left the grid at ({:.6g}, {:.6g}) m, t = {} s: make the grid "
          "larger",
          p, particles_.position[p][0], particles_.position[p][1], time_ + dt));
  }
}

void DepthAveragedSolver::split_stretched_points() {
  if (settings_.split_length <= 0.0) return;
  const std::size_t before = particles_.size();
  for (std::size_t p = 0; p < before; ++p) {
    for (int edge = 0; edge < 2; ++edge) {
      const Vec<2> e = particles_.edges[p].col(edge);
      // The edge's length in cells of the grid along it.
      const double cells =
          std::hypot(e[0] / settings_.grid.spacing[0], e[1] / settings_.grid.spacing[1]);
      if (cells > settings_.split_length) {
        particles_.split(p, edge);
        break;  // the other edge is looked at next step
      }
    }
  }
}

// Eq. 26: a point whose depth exceeds its crack depth, or whose in-plane
// stress reached Mohr-Coulomb, yields, and its bonds break with its areal
// strain; its structures break up as it dilates (eq. 28)
// and are gone with the last bond.
void DepthAveragedSolver::degrade_cohesion(double dt) {
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto& m = materials_[static_cast<std::size_t>(particles_.material[p])];
    if (!m.degradation.enabled() || particles_.damage[p] >= 1.0) continue;
    const double z_c = EarthPressure::crack_depth(
        earth_pressure_coefficient(p), unit_weight(p, submersion(p).relieved_density_depth),
        cohesion(p));
    if (particles_.depth(p) <= z_c && !particles_.yielded[p]) continue;
    const double strain = dt * particles_.areal_strain_rate[p];
    const double damage = particles_.damage[p];
    particles_.damage[p] = m.degradation.damage_after(damage, strain);
    const double share = particles_.structured_share[p];
    const double new_share =
        particles_.damage[p] >= 1.0 ? 0.0 : m.structured_share_after(share, damage, strain);
    particles_.structured_share[p] = new_share;
    // Eq. 27: the confined fluid goes at the structures' rate, its volume
    // and mass leaving the column (its momentum with them).
    if (share > 0.0 && particles_.confined_fluid[p] > 0.0) {
      const double released = particles_.confined_fluid[p] * (share - new_share) / share;
      particles_.confined_fluid[p] -= released;
      particles_.released_fluid[p] += released;
      particles_.volume[p] -= released;
      particles_.mass[p] -= settings_.confined_fluid_density * released;
    }
  }
}

std::vector<double> DepthAveragedSolver::take_released_fluid() {
  std::vector<double> released(particles_.size(), 0.0);
  released.swap(particles_.released_fluid);
  return released;
}

void DepthAveragedSolver::apply_impulse(std::span<const Vec<2>> impulse) {
  if (impulse.size() != particles_.size())
    throw std::invalid_argument(
        fmt::format("an impulse for {} points on {} points", impulse.size(), particles_.size()));
  for (std::size_t p = 0; p < particles_.size(); ++p)
    particles_.velocity[p] += impulse[p] / particles_.mass[p];
}

}  // namespace mpm

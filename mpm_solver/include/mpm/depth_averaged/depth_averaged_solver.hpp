#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "mpm/depth_averaged/depth_averaged_material.hpp"
#include "mpm/depth_averaged/depth_averaged_particles.hpp"
#include "mpm/depth_averaged/earth_pressure.hpp"
#include "mpm/depth_averaged/terrain.hpp"
#include "mpm/shape/grid_geometry.hpp"

namespace mpm {

// What a grid face does to the mass: slip (no normal motion) or stick.
enum class GroundWall { slip, stick };

// A fixed obstacle standing on the ground: the grid's nodes inside the box
// are held still, as a stick wall, so the mass stops against it and flows
// around it.
struct GroundObstacle {
  Vec<2> min = Vec<2>::Zero(), max = Vec<2>::Zero();  // [m]
};

// A lake the mass moves in, its surface level at a world elevation.
struct StillWater {
  double density = 1000.0;  // rho_f [kg/m^3]
  double level = 0.0;       // world elevation of the surface [m] (Terrain::height_of_level)
};

struct DepthAveragedSettings {
  GridGeometry<2> grid;  // in the plane of the ground
  Terrain terrain;
  EarthPressure earth_pressure;
  std::array<GroundWall, 4> walls{GroundWall::slip, GroundWall::slip, GroundWall::slip,
                                  GroundWall::slip};  // x_min, x_max, y_min, y_max
  std::vector<GroundObstacle> obstacles;
  // Share of FLIP in the points' velocity update (the rest PIC): PIC's
  // smoothing over the kernel slows a dam break's thin front (its 1 %-depth
  // point 8 % behind Mangeney et al.'s at 15 s, against 1 % with 0.99).
  double flip_fraction = 0.99;
  // Time step as a fraction of a cell crossed by the fastest point plus its
  // gravity wave, sqrt(K g cos(theta) h).
  double courant = 0.4;
  // A point whose edge grows longer than this many grid cells (in the edge's
  // direction) is split in two; 0 never splits.
  double split_length = 1.0;
  // A fluid at rest around the mass; a coupled fluid sets its surface
  // through DepthAveragedSolver::set_fluid_surface instead.
  std::optional<StillWater> still_water;
  // rho_f of the fluid the columns confine: what they lose with the volume
  // they release (eq. 27) [kg/m^3].
  double confined_fluid_density = 1000.0;
};

// The depth-averaged mass of van den Bout et al. (OpenLISEM Hazard) as
// material points in the plane of the ground, on a quadratic B-spline grid.
// Each point is a column of fixed volume V_p whose plan area A_p follows the
// flow's areal strain, so its depth is h_p = V_p / A_p; points stretched
// past the grid's cells are split, so a spreading mass stays resolved down
// to its thin edges. The grid's depth h_i = sum_p N_ip V_p / a_i (a_i the
// integral of N_i) is what the mass looks like from outside (output, a
// fluid). The depth-integrated momentum balance per unit ground area is
//
//   d(rho h u)/dt = rho h [g sin(theta) e_x - g cos(theta) grad b]   (eq. 54: g^x, the bed)
//                   - grad T(h, K, c)                                  (eqs. 42-44)
//                   - rho g cos(theta) h tan(delta) u / |u|            (eqs. 36, 37)
//
// with T the lateral thrust of EarthPressure (Bell's cohesion and tension
// cracks), and, for a material with a Young's modulus, + div(h sigma), sigma
// the in-plane stress (InPlaneStress: eq. 43's last term), which holds a
// cohesive block together while its parts are driven apart and lets a weak
// one tear. In a fluid of density rho_f whose free surface stands at height
// eta_f above the reference plane, the submerged part s = clamp(eta_f - b, 0, h)
// of a column is pushed by the fluid's hydrostatic pressure gradient and
// buoyed, -rho_f g cos(theta) s grad(eta_f - b) (eq. 54's p_bu term: on a
// sloping bed the buoyancy takes its share of the weight's push along the
// ground, whatever reaches the base; in a still lake over the inclined
// plane grad eta_f = tan(theta) e_x cancels rho_f s of the drive), and its
// base is relieved by the fluid pressure that reaches it through the solids,
// B_eff rho_f g cos(theta) s with B_eff = (1 - f_sc) + f_sc B (eq. 39): the
// friction and the thrust take the weight rho h - B_eff rho_f s. The thrust's weak form gives each
// node f_i = sum_p A_p T_p grad N_ip; the basal friction acts on the nodes' momentum after all
// other forces, never more than stops them (a resting mass stays at rest when
// tan(delta) exceeds its driving slope). Fragmentation (eq. 26) degrades the
// cohesion of a yielding point (h > z_c) by its areal strain.
class DepthAveragedSolver {
 public:
  // Throws std::invalid_argument for a bad setting, material or point.
  DepthAveragedSolver(DepthAveragedSettings settings, std::vector<DepthAveragedMaterial> materials,
                      DepthAveragedParticles particles);

  // The largest step the Courant limit allows now [s] (infinite for a mass at rest with no depth).
  double stable_time_step() const;
  // One step of dt: throws cosim::NumericalError when a point leaves the grid
  // or a value turns non-finite.
  void step(double dt);
  // Steps of at most the stable one until `end_time` [s]; returns the steps taken.
  long advance_to(double end_time);

  double time() const { return time_; }
  const DepthAveragedSettings& settings() const { return settings_; }
  const std::vector<DepthAveragedMaterial>& materials() const { return materials_; }
  const DepthAveragedParticles& particles() const { return particles_; }
  // The cohesion a point has left [Pa].
  double cohesion(std::size_t p) const;

  // The free surface of a fluid around the mass: its density and its height
  // above the reference plane at each grid node (B-spline coefficients,
  // x fastest, as nodal_depth); an empty surface removes the fluid.
  // Throws std::invalid_argument for a wrong size or a non-finite value.
  void set_fluid_surface(double density, std::vector<double> surface_at_nodes);
  double fluid_surface_at(const Vec<2>& x) const;
  bool has_fluid() const { return !fluid_surface_.empty(); }
  // The structured share f_sc a point has left.
  double structured_share(std::size_t p) const { return particles_.structured_share[p]; }
  // The fluid each point released since the last call [m^3], set back to zero.
  std::vector<double> take_released_fluid();
  // Adds impulse[p] / m_p to each point's velocity (an impulse from outside,
  // e.g. a fluid's drag). Throws std::invalid_argument for a wrong size.
  void apply_impulse(std::span<const Vec<2>> impulse);

  // The depth field of the last transfer: its values at the grid's nodes
  // (B-spline coefficients, x fastest), the nodes' positions, and its value
  // anywhere on the grid.
  const std::vector<double>& nodal_depth() const { return depth_; }
  Vec<2> node_position(std::size_t node) const;
  std::array<int, 2> nodes_per_direction() const { return nodes_; }
  double depth_at(const Vec<2>& x) const;
  // The grid's velocity at x after the last step, sum N_i p_i / sum N_i m_i
  // (zero where the mass is not).
  Vec<2> velocity_at(const Vec<2>& x) const;

 private:
  // The step, in order.
  void clear_grid();
  void transfer_points_to_grid();  // mass, momentum, volume, driving force, friction capacity
  void compute_depth();            // h_i = V_i / a_i, then h_p
  void add_internal_forces();      // the lateral thrust and the in-plane stress
  void advance_grid_momentum(double dt);
  void apply_walls();
  void apply_basal_friction(double dt);
  void transfer_grid_to_points(double dt);
  void update_in_plane_stress(double dt);
  void degrade_cohesion(double dt);
  void split_stretched_points();

  void compute_node_areas();
  double earth_pressure_coefficient(std::size_t p) const;
  // T of point p with its relief from the last P2G [N/m].
  double lateral_thrust(std::size_t p) const;
  // The fluid's relief of the column's weight per unit area, B_eff rho_f s, and
  // the submerged depth s [m] at point p (both 0 without a fluid).
  struct Submersion {
    double depth = 0.0;
    double relieved_density_depth = 0.0;  // B_eff rho_f s [kg/m^2]
  };
  Submersion submersion(std::size_t p) const;
  Submersion submersion_below(std::size_t p, double surface) const;  // surface eta_f at the point
  // g cos(theta) (rho h - relieved) / h [N/m^3]
  double unit_weight(std::size_t p, double relieved_density_depth) const;

  DepthAveragedSettings settings_;
  std::vector<DepthAveragedMaterial> materials_;
  DepthAveragedParticles particles_;
  double time_ = 0.0;

  std::array<int, 2> nodes_{};
  std::vector<double> area_;          // a_i
  std::vector<double> mass_;          // m_i
  std::vector<Vec<2>> momentum_;      // at the step's start
  std::vector<Vec<2>> new_momentum_;  // at its end
  std::vector<Vec<2>> force_;         // driving force and thrust
  std::vector<double> volume_;        // V_i
  std::vector<double> depth_;         // h_i
  std::vector<double> friction_;      // sum_p N_ip m_p g cos(theta) tan(delta_p)
  std::vector<char> stopped_;         // friction stopped the node this step
  std::vector<std::size_t> held_;     // nodes inside an obstacle
  double fluid_density_ = 0.0;
  std::vector<double> fluid_surface_;  // eta_f at the nodes; empty without a fluid
  std::vector<double> relieved_;       // B_eff rho_f s per point, from the last P2G
};

}  // namespace mpm

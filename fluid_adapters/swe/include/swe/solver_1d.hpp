#pragma once

#include <vector>

#include "swe/boundary.hpp"
#include "swe/solver.hpp"

namespace swe {

// The 1D shallow-water equations (Zheng et al., eq. 24) on non-uniform cells
// x_0 < x_1 < ... < x_n (Sec. 3.2): Roe, HLL or HLLC fluxes, MUSCL slopes on
// the non-uniform spacing, hydrostatic reconstruction of the bed source
// (well-balanced with dry cells), SSP-RK2 in time, semi-implicit Manning
// friction (eqs. 35-36), CFL step (eq. 37).
//
// Reconstruction: depth h, surface eta = h + B and velocity u (0 in dry
// cells) get limited slopes from the one-sided differences divided by the
// centre distances; each slope is then scaled down so that both face values
// lie between the cell's value and the neighbour's on that side (bounded and
// non-negative on any spacing, face mean = cell mean). Face bed = eta - h.
//
// Boundaries, through two ghost cells per side (bed = adjacent interior bed,
// width = mirrored interior width):
//   wall              ghosts mirror the two interior cells, discharge negated;
//   transmissive      both ghosts copy the adjacent cell;
//   inflow_discharge  ghost discharge = value, pointing into the domain; ghost
//                     depth = adjacent depth, but at least the critical depth
//                     (value^2 / g)^(1/3) so water also enters a dry channel;
//                     the mass flux through the boundary face is the value
//                     itself (exactly value * dt enters per step; the Riemann
//                     flux of the ghost state alone passes about the mean of
//                     the ghost and interior discharges), its momentum flux
//                     the Riemann solver's;
//   fixed_depth       ghost depth h_b = value, velocity from the Riemann
//                     invariant leaving the domain: on the right side
//                     u_b = u_i + 2 (sqrt(g h_i) - sqrt(g h_b)) (u + 2c kept),
//                     on the left side u_b = u_i - 2 (sqrt(g h_i) - sqrt(g h_b))
//                     (u - 2c kept).
//
// Stable step (eq. 37 per face, local width):
//   dt = C_r * min over faces of min(dx_l, dx_r) / s_face,
//   s_face = max(|u^| + c^ (Roe averages of the two cells, both wet),
//                |u_l| + c_l, |u_r| + c_r),
// where a wet cell next to a dry one (h < dry_depth) counts |u| + 2c, the
// speed of a front running onto the dry bed; ghost cells take part, so the
// boundary faces count. +infinity when no cell holds water.
struct Boundaries1d {
  Boundary left;
  Boundary right;
};

class Solver1d final : public Solver {
 public:
  // Throws cosim::InputError for fewer than one cell or non-increasing edges.
  Solver1d(std::vector<double> edges, Physics physics, Scheme scheme, Boundaries1d boundaries);
  ~Solver1d() override;

  int dimension() const override { return 1; }
  std::size_t cell_count() const override;
  cosim::MeshGeometry cells() const override;
  double cell_size(std::size_t cell) const override;
  std::size_t cell_at(double x, double y = 0.0) const override;

  void set_state(std::span<const double> h, std::span<const double> hu,
                 std::span<const double> hv) override;
  void set_bed(std::span<const double> bed) override;
  double stable_time_step() const override;
  void step(double dt) override;
  void save_state() override;
  void restore_state() override;
  void write_state(cosim::StateFileWriter& out) const override;
  void read_state(const cosim::StateFileReader& in) override;

  std::span<const double> depth() const override;
  std::span<const double> discharge_x() const override;
  std::span<const double> discharge_y() const override { return {}; }
  std::span<const double> bed() const override;

  Totals totals() const override;
  const Physics& physics() const override;
  const Scheme& scheme() const override;

  const std::vector<double>& edges() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swe

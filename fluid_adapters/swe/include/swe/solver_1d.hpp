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

  void set_state(std::span<const double> h, std::span<const double> hu, std::span<const double> hv) override;
  void set_bed(std::span<const double> bed) override;
  double stable_time_step() const override;
  void step(double dt) override;

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

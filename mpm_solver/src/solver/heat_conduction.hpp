#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "grid_boundaries.hpp"
#include "mpm/case/case_description.hpp"
#include "mpm/grid/grid.hpp"
#include "mpm/particles/particles.hpp"
#include "mpm/shape/grid_geometry.hpp"
#include "mpm/shape/stencil.hpp"
#include "mpm/solver/grid_partition.hpp"
#include "particle_bins.hpp"

namespace mpm::detail {

// Explicit heat conduction in the thermal bodies on the background grid,
// one temperature field shared by every thermal body (bodies that touch
// are in perfect thermal contact). With C_p = m_p c_p the heat capacity of
// a point, k_eff,p its conductivity and x_i the positions of the grid
// values, one step of dt is
//   C_i = sum_p N_ip C_p                                          (eq. 39)
//   T_i = sum_p N_ip C_p (T_p + grad T_p . (x_i - x_p)) / C_i
//   grad T_p = sum_i grad N_ip T_i                                 (eq. 93)
//   H_i = -sum_p V_p k_eff,p grad N_ip . grad T_p + sum_p N_ip Q_p
//   dT_i = dt H_i / C_i                                            (eqs. 55-56)
//   T_p += sum_i N_ip dT_i                                         (eqs. 87, 92)
// (Tran et al., MPMICE), Q_p the external heat rate of a point (coupling).
// Since sum_i grad N_ip = 0 the conduction rates add up to zero and
// sum_p C_p T_p changes by exactly dt sum_p Q_p when no face holds a
// temperature, whatever T_i is. A porous skeleton conducts with its share
// of the section, k_eff = (1 - n_p) k_s, the paper's rho_bar_s beta_s; the
// pore fluid conducts in the fluid solver.
//
// The grid temperature takes each point's gradient of the step before (the
// Taylor term; zero at the start) besides its value: the plain mean
// sum N C T_p / C_i sits at the points' mean position, which near a face is
// a fraction of a cell inside the grid value (and for the B-spline also at
// the control point next to it), and with that bias the points of the face
// cells carry an O(h) error. The gradient is the one of the step's start:
// the end-of-step field, with its large dT_i at grid values that points
// barely reach, feeds back unstably.
//
// Grid values on a fixed-temperature face (the mean of the faces' values
// where faces meet) are at the face temperature in grad T_p, and their
// change over the step is T_face - T_i, so the points' field there ends
// the step at T_face: the way the velocity solve treats fixed faces.
//
// Left out: the heating by plastic work and by contact friction (Delta W
// and Delta W_fric of eq. 55); the plastic dissipation is reported in the
// mechanical totals instead.
template <int Dim>
class HeatConduction {
 public:
  // `body_conductivity`: k of each body's solid [W/(m K)] (0 when not thermal).
  HeatConduction(const ThermalSpec& spec, std::vector<double> body_conductivity,
                 const FaceValues& faces, const Grid<Dim>& grid)
      : spec_(spec), conductivity_(std::move(body_conductivity)) {
    attach(faces, grid, nullptr);
  }

  // The grid values it works on: on a rank of a decomposed run, the stored
  // planes of `grid` (again whenever they change), whose ghosts `partition`
  // sums into their owners and refreshes from them.
  void attach(const FaceValues& faces, const Grid<Dim>& grid, GridPartition<Dim>* partition) {
    partition_ = partition;
    std::map<std::size_t, std::pair<double, int>>
        held;  // grid value: sum of face temperatures, faces
    for (std::size_t f = 0; f < spec_.faces.size(); ++f) {
      if (spec_.faces[f].kind != FaceTemperature::Kind::fixed) continue;
      for (const std::size_t v : faces[f]) {
        held[v].first += spec_.faces[f].temperature;
        ++held[v].second;
      }
    }
    fixed_.clear();
    for (const auto& [v, sum] : held) fixed_.push_back({v, sum.first / sum.second});
    change_at_fixed_.assign(fixed_.size(), 0.0);
    odd_heat_capacity_.assign(grid.size(), 0.0);
    odd_temperature_.assign(grid.size(), 0.0);
    odd_heat_rate_.assign(grid.size(), 0.0);
    node_position_.resize(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i)
      node_position_[i] = grid.position(grid.flat_of_stored(i));
    owned_ = {grid.owned_begin(), grid.owned_end()};
    first_ = grid.first_value();
  }

  double conductivity(const Particles<Dim>& particles, std::size_t p) const {
    return (1.0 - particles.porosity[p]) * conductivity_[particles.body[p]];
  }

  // C_i, T_i and the external heat rate sum_p N_ip Q_p into grid.heat_rate;
  // the face temperatures replace T_i on the fixed faces.
  template <class Kernel>
  void interpolate_to_grid(const Particles<Dim>& particles, const ParticleBins& bins,
                           const GridGeometry<Dim>& geometry, Grid<Dim>& grid) {
    std::fill(grid.heat_capacity.begin(), grid.heat_capacity.end(), 0.0);
    std::fill(grid.temperature.begin(), grid.temperature.end(), 0.0);
    std::fill(grid.heat_rate.begin(), grid.heat_rate.end(), 0.0);
    bins.scatter([&](std::size_t p, int parity) {
      const double C = particles.heat_capacity[p];
      if (C <= 0.0) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      const double T = particles.temperature[p];
      const Vec<Dim>& gradient = particles.temperature_gradient[p];
      const Vec<Dim>& x = particles.position[p];
      const double Q = particles.external_heat[p];
      double* heat_capacity = parity == 0 ? grid.heat_capacity.data() : odd_heat_capacity_.data();
      double* temperature = parity == 0 ? grid.temperature.data() : odd_temperature_.data();
      double* heat_rate = parity == 0 ? grid.heat_rate.data() : odd_heat_rate_.data();
      stencil.for_each([&](std::size_t flat, double N, const Vec<Dim>&) {
        const std::size_t i = flat - first_;
        heat_capacity[i] += N * C;
        temperature[i] += N * C * (T + gradient.dot(node_position_[i] - x));
        heat_rate[i] += N * Q;
      });
    });
    if (partition_) {
      const GridArray sums[] = {one(grid.heat_capacity), one(grid.temperature),
                                one(grid.heat_rate),     one(odd_heat_capacity_),
                                one(odd_temperature_),   one(odd_heat_rate_)};
      partition_->accumulate(sums);
    }
    add_odd_partials(grid.heat_capacity, odd_heat_capacity_, false);
    add_odd_partials(grid.temperature, odd_temperature_, false);
    add_odd_partials(grid.heat_rate, odd_heat_rate_, false);
    for (std::size_t i = 0; i < grid.size(); ++i)
      grid.temperature[i] =
          grid.heat_capacity[i] > 0.0 ? grid.temperature[i] / grid.heat_capacity[i] : 0.0;
    for (std::size_t k = 0; k < fixed_.size(); ++k)
      change_at_fixed_[k] = fixed_[k].temperature - grid.temperature[fixed_[k].value];
    for (const FixedValue& fixed : fixed_) grid.temperature[fixed.value] = fixed.temperature;
    if (partition_) {
      // The ghosts take their owners' T_i and C_i; their rates start again
      // from 0 for the conduction's partial sums.
      const GridArray refreshed[] = {one(grid.temperature), one(grid.heat_capacity)};
      partition_->exchange(refreshed);
      for (std::size_t i = 0; i < grid.size(); ++i)
        if (!owns(i)) grid.heat_rate[i] = 0.0;
    }
  }

  // grad T_p, kept for the next step's transfer, and the conduction rates
  // -sum_p V_p k_eff,p grad N_ip . grad T_p added to grid.heat_rate.
  template <class Kernel>
  void conduct(Particles<Dim>& particles, const ParticleBins& bins,
               const GridGeometry<Dim>& geometry, Grid<Dim>& grid) {
    bins.scatter([&](std::size_t p, int parity) {
      if (particles.heat_capacity[p] <= 0.0) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      Vec<Dim>& gradient = particles.temperature_gradient[p];
      gradient.setZero();
      stencil.for_each([&](std::size_t flat, double, const Vec<Dim>& grad_N) {
        gradient += grad_N * grid.temperature[flat - first_];
      });
      const double Vk = particles.volume[p] * conductivity(particles, p);
      if (Vk <= 0.0) return;
      const Vec<Dim> flux = Vk * gradient;
      double* heat_rate = parity == 0 ? grid.heat_rate.data() : odd_heat_rate_.data();
      stencil.for_each([&](std::size_t flat, double, const Vec<Dim>& grad_N) {
        heat_rate[flat - first_] -= grad_N.dot(flux);
      });
    });
    if (partition_) {
      const GridArray sums[] = {one(grid.heat_rate), one(odd_heat_rate_)};
      partition_->accumulate(sums);
    }
    add_odd_partials(grid.heat_rate, odd_heat_rate_, false);
  }

  // dT_i over the step; returns the heat the fixed-temperature faces put in
  // [J] (on a rank: through the values it owns).
  double integrate(double dt, Grid<Dim>& grid) const {
    for (std::size_t i = 0; i < grid.size(); ++i)
      grid.temperature_change[i] =
          grid.heat_capacity[i] > 0.0 ? dt * grid.heat_rate[i] / grid.heat_capacity[i] : 0.0;
    double through_faces = 0.0;
    for (std::size_t k = 0; k < fixed_.size(); ++k) {
      const std::size_t i = fixed_[k].value;
      if (!(grid.heat_capacity[i] > 0.0)) continue;
      grid.temperature_change[i] = change_at_fixed_[k];
      if (owns(i))
        through_faces +=
            grid.heat_capacity[i] * grid.temperature_change[i] - dt * grid.heat_rate[i];
    }
    if (partition_) {
      const GridArray changed[] = {one(grid.temperature_change)};
      partition_->exchange(changed);
    }
    return through_faces;
  }

  template <class Kernel>
  void interpolate_to_particles(Particles<Dim>& particles, const ParticleBins& bins,
                                const GridGeometry<Dim>& geometry, const Grid<Dim>& grid) const {
    bins.per_slab([&](std::size_t p) {
      if (particles.heat_capacity[p] <= 0.0) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      double dT = 0.0;
      stencil.for_each([&](std::size_t flat, double N, const Vec<Dim>&) {
        dT += N * grid.temperature_change[flat - first_];
      });
      particles.temperature[p] += dT;
    });
  }

  // The explicit conduction limit safety h^2 / (2 Dim max_p kappa_p) with the
  // diffusivity kappa_p = k_eff,p V_p / C_p; infinite when nothing conducts.
  double stable_time_step(const Particles<Dim>& particles, double min_spacing,
                          double safety) const {
    double kappa = 0.0;
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (particles.heat_capacity[p] > 0.0)
        kappa = std::max(
            kappa, conductivity(particles, p) * particles.volume[p] / particles.heat_capacity[p]);
    if (partition_) kappa = partition_->max(kappa);
    return kappa > 0.0 ? safety * min_spacing * min_spacing / (2.0 * Dim * kappa)
                       : std::numeric_limits<double>::infinity();
  }

 private:
  static GridArray one(std::vector<double>& values) { return {values.data(), 1, 1}; }
  bool owns(std::size_t i) const { return i >= owned_[0] && i < owned_[1]; }

  struct FixedValue {
    std::size_t value = 0;
    double temperature = 0.0;  // mean over the faces it lies on
  };

  ThermalSpec spec_;
  std::vector<double> conductivity_;  // per body
  GridPartition<Dim>* partition_ = nullptr;
  std::array<std::size_t, 2> owned_{};  // the stored values this rank owns
  std::size_t first_ = 0;               // the stencils' flat index of stored value 0
  std::vector<FixedValue> fixed_;
  std::vector<double> change_at_fixed_;  // per fixed value, this step
  std::vector<Vec<Dim>> node_position_;  // per grid value
  // The odd slabs' partial sums of the scattered arrays (ParticleBins).
  std::vector<double> odd_heat_capacity_, odd_temperature_, odd_heat_rate_;
};

}  // namespace mpm::detail

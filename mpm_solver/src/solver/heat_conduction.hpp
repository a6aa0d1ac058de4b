#pragma once

#include <algorithm>
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
#include "particle_bins.hpp"

namespace mpm::detail {

// Explicit heat conduction in the thermal bodies on the background grid,
// one temperature field shared by every thermal body (bodies that touch
// are in perfect thermal contact). With C_p = m_p c_p the heat capacity of
// a point and k_eff,p its conductivity, one step of dt is
//   C_i = sum_p N_ip C_p,   T_i = sum_p N_ip C_p T_p / C_i     (eq. 39)
//   grad T_p = sum_i grad N_ip T_i                             (eq. 93)
//   H_i = -sum_p V_p k_eff,p grad N_ip . grad T_p + sum_p N_ip Q_p
//   dT_i = dt H_i / C_i                                        (eqs. 55-56)
//   T_p += sum_i N_ip dT_i                                     (eqs. 87, 92)
// (Tran et al., MPMICE), Q_p the external heat rate of a point (coupling).
// Since sum_i grad N_ip = 0 the conduction rates add up to zero and
// sum_p C_p T_p changes by exactly dt sum_p Q_p when no face holds a
// temperature. A porous skeleton conducts with its share of the section,
// k_eff = (1 - n_p) k_s, the paper's rho_bar_s beta_s; the pore fluid
// conducts in the fluid solver.
//
// Grid values on a fixed-temperature face (the mean of the faces' values
// where faces meet) enter grad T_p at the face's temperature. Their change
// over the step brings the points' value there to what a field through
// T_face has at the points' mean position: T_i from the points is their
// heat-capacity-weighted mean, whose points sit on average a distance d_i
// inside the face, so its target is T_face + (d_i / D) (T_j - T_face), with
// T_j the value of the next grid value inward and D the distance of its
// points' mean from the face. A linear profile through T_face is then
// steady, where holding T_i itself at T_face would pull the points of the
// face cells off it by O(h grad T) (first order instead of second).
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
      : conductivity_(std::move(body_conductivity)) {
    std::map<std::size_t, FixedValue> held;
    for (int f = 0; f < 2 * Dim; ++f) {
      const FaceTemperature& face = spec.faces[static_cast<std::size_t>(f)];
      if (face.kind != FaceTemperature::Kind::fixed) continue;
      const int axis = f / 2;
      const int inward = f % 2 == 0 ? 1 : -1;
      for (const std::size_t v : faces[static_cast<std::size_t>(f)]) {
        auto index = grid.unflat(v);
        index[static_cast<std::size_t>(axis)] += inward;
        FixedValue& fixed = held[v];
        fixed.value = v;
        fixed.faces.push_back(
            {face.temperature, grid.flat(index), axis, static_cast<double>(inward)});
      }
    }
    for (auto& [v, fixed] : held) {
      for (const auto& face : fixed.faces)
        fixed.temperature += face.temperature / static_cast<double>(fixed.faces.size());
      fixed_.push_back(std::move(fixed));
    }
    change_at_fixed_.assign(fixed_.size(), 0.0);
  }

  double conductivity(const Particles<Dim>& particles, std::size_t p) const {
    return (1.0 - particles.porosity[p]) * conductivity_[particles.body[p]];
  }

  // C_i, T_i and the external heat rate sum_p N_ip Q_p into grid.heat_rate;
  // the fixed face temperatures replace T_i on their faces.
  template <class Kernel>
  void interpolate_to_grid(const Particles<Dim>& particles, const ParticleBins& bins,
                           const GridGeometry<Dim>& geometry, Grid<Dim>& grid) {
    std::fill(grid.heat_capacity.begin(), grid.heat_capacity.end(), 0.0);
    std::fill(grid.temperature.begin(), grid.temperature.end(), 0.0);
    std::fill(grid.heat_rate.begin(), grid.heat_rate.end(), 0.0);
    if (!fixed_.empty()) centroid_.assign(grid.size(), Vec<Dim>::Zero());
    bins.scatter([&](std::size_t p) {
      const double C = particles.heat_capacity[p];
      if (C <= 0.0) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      const double CT = C * particles.temperature[p];
      const double Q = particles.external_heat[p];
      const Vec<Dim> Cx = C * particles.position[p];
      stencil.for_each([&](std::size_t i, double N, const Vec<Dim>&) {
        grid.heat_capacity[i] += N * C;
        grid.temperature[i] += N * CT;
        grid.heat_rate[i] += N * Q;
        if (!centroid_.empty()) centroid_[i] += N * Cx;
      });
    });
    for (std::size_t i = 0; i < grid.size(); ++i)
      grid.temperature[i] =
          grid.heat_capacity[i] > 0.0 ? grid.temperature[i] / grid.heat_capacity[i] : 0.0;
    for (std::size_t k = 0; k < fixed_.size(); ++k)
      change_at_fixed_[k] = target(fixed_[k], grid) - grid.temperature[fixed_[k].value];
    for (const FixedValue& fixed : fixed_) grid.temperature[fixed.value] = fixed.temperature;
  }

  // Adds the conduction rates -sum_p V_p k_eff,p grad N_ip . grad T_p to grid.heat_rate.
  template <class Kernel>
  void conduct(const Particles<Dim>& particles, const ParticleBins& bins,
               const GridGeometry<Dim>& geometry, Grid<Dim>& grid) const {
    bins.scatter([&](std::size_t p) {
      if (particles.heat_capacity[p] <= 0.0) return;
      const double Vk = particles.volume[p] * conductivity(particles, p);
      if (Vk <= 0.0) return;
      Stencil<Dim, Kernel> stencil;
      stencil.evaluate(particles.position[p], particles.half_length[p], geometry);
      Vec<Dim> gradient = Vec<Dim>::Zero();
      stencil.for_each([&](std::size_t i, double, const Vec<Dim>& grad_N) {
        gradient += grad_N * grid.temperature[i];
      });
      const Vec<Dim> flux = Vk * gradient;
      stencil.for_each([&](std::size_t i, double, const Vec<Dim>& grad_N) {
        grid.heat_rate[i] -= grad_N.dot(flux);
      });
    });
  }

  // dT_i over the step; returns the heat the fixed-temperature faces put in [J].
  double integrate(double dt, Grid<Dim>& grid) const {
    for (std::size_t i = 0; i < grid.size(); ++i)
      grid.temperature_change[i] =
          grid.heat_capacity[i] > 0.0 ? dt * grid.heat_rate[i] / grid.heat_capacity[i] : 0.0;
    double through_faces = 0.0;
    for (std::size_t k = 0; k < fixed_.size(); ++k) {
      const std::size_t i = fixed_[k].value;
      if (!(grid.heat_capacity[i] > 0.0)) continue;
      grid.temperature_change[i] = change_at_fixed_[k];
      through_faces += grid.heat_capacity[i] * grid.temperature_change[i] - dt * grid.heat_rate[i];
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
      stencil.for_each(
          [&](std::size_t i, double N, const Vec<Dim>&) { dT += N * grid.temperature_change[i]; });
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
    return kappa > 0.0 ? safety * min_spacing * min_spacing / (2.0 * Dim * kappa)
                       : std::numeric_limits<double>::infinity();
  }

 private:
  struct HeldFace {
    double temperature = 0.0;
    std::size_t inward = 0;  // the next grid value inward
    int axis = 0;
    double inward_sign = 1.0;
  };
  struct FixedValue {
    std::size_t value = 0;
    double temperature = 0.0;  // mean over its faces
    std::vector<HeldFace> faces;
  };

  // What the points' value at a fixed grid value should be (see above),
  // averaged over the faces it lies on; before the face temperatures
  // replace the points' values.
  double target(const FixedValue& fixed, const Grid<Dim>& grid) const {
    const std::size_t i = fixed.value;
    if (!(grid.heat_capacity[i] > 0.0)) return fixed.temperature;
    const Vec<Dim> centroid = centroid_[i] / grid.heat_capacity[i];
    double sum = 0.0;
    for (const HeldFace& face : fixed.faces) {
      double T = face.temperature;
      const std::size_t j = face.inward;
      if (grid.heat_capacity[j] > 0.0) {
        const double x = grid.position(i)[face.axis];
        const double D = face.inward_sign * (centroid_[j][face.axis] / grid.heat_capacity[j] - x);
        const double d = face.inward_sign * (centroid[face.axis] - x);
        if (D > 0.0) T += std::clamp(d / D, 0.0, 1.0) * (grid.temperature[j] - face.temperature);
      }
      sum += T;
    }
    return sum / static_cast<double>(fixed.faces.size());
  }

  std::vector<double> conductivity_;  // per body
  std::vector<FixedValue> fixed_;
  std::vector<double> change_at_fixed_;  // per fixed value, this step
  std::vector<Vec<Dim>> centroid_;       // sum_p N_ip C_p x_p, when a face is held
};

}  // namespace mpm::detail

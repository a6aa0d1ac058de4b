#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "mpm/case/case_description.hpp"
#include "mpm/material/material.hpp"
#include "mpm/particles/particles.hpp"
#include "objective_stress.hpp"

namespace mpm::detail {

// Intrinsic permeability of a porous point at porosity n [m^2].
inline double permeability(const PorousSpec& porous, double n) {
  const double d = porous.grain_size;
  switch (porous.permeability_model) {
    case PermeabilityModel::constant:
      return porous.permeability;
    case PermeabilityModel::kozeny_carman_pan:  // Pan et al. 2021, eq. 76
      return d * d * n * n * n / (150.0 * (1.0 - n) * (1.0 - n));
    case PermeabilityModel::kozeny_carman_tran: {  // Tran et al., MPMICE, eq. 32 with K = k rho g /
                                                   // mu (eq. 31)
      const double phi_s = 1.0 - n;
      return d * d * n * n * n / (180.0 * phi_s * phi_s);
    }
  }
  return porous.permeability;
}

// The cell average used against volumetric locking for one point: `own` and
// `cell` are the point's and its cell's volume-weighted mean of det(dF)
// (F-bar) or of tr(L) dt (B-bar).
struct VolumetricAverage {
  LockingMitigation kind = LockingMitigation::none;
  double own = 0.0;
  double cell = 0.0;
};

// Kinematics and stress of one deformable point for a step with velocity
// gradient L. Returns the stress work of the step, V (sigma_n + sigma_n+1)/2 : d eps [J].
template <int Dim>
double update_point(const Material& material, const Mat<Dim>& L, double dt,
                    const VolumetricAverage& average, const std::optional<PorousSpec>& porous,
                    std::size_t p, Particles<Dim>& particles) {
  Mat<Dim> increment = Mat<Dim>::Identity() + dt * L;  // Tran et al., MPMICE, eq. 94
  if (average.kind == LockingMitigation::fbar && average.own > 0.0 && average.cell > 0.0)
    increment *= std::pow(average.cell / average.own, 1.0 / Dim);
  const Mat<Dim> displacement_gradient = increment - Mat<Dim>::Identity();
  Mat<Dim> strain = 0.5 * (displacement_gradient + displacement_gradient.transpose());
  if (average.kind == LockingMitigation::bbar)
    strain.diagonal().array() += (average.cell - average.own) / Dim;
  const Mat<Dim> spin = 0.5 * (displacement_gradient - displacement_gradient.transpose());

  // B-bar: the point's volume (and F) follow the cell-averaged dilatation its
  // stress sees; with the point's own, the volume drifts in the zero-energy
  // modes the averaging leaves free.
  Mat<Dim> kinematic_increment = increment;
  if (average.kind == LockingMitigation::bbar && 1.0 + average.own > 0.0 &&
      1.0 + average.cell > 0.0)
    kinematic_increment *= std::pow((1.0 + average.cell) / (1.0 + average.own), 1.0 / Dim);
  const Mat<Dim> F_old = particles.deformation_gradient[p];
  const Mat<Dim> F_new = kinematic_increment * F_old;
  const double J = F_new.determinant();
  if (!(J > 0.0)) {
    particles.volume[p] = std::numeric_limits<double>::quiet_NaN();
    return 0.0;
  }
  particles.deformation_gradient[p] = F_new;
  particles.volume[p] = J * particles.initial_volume[p];  // Pan et al. 2021, eq. 74
  if (porous) {
    // Pan et al. 2021, eq. 75, capped as the text after eq. 76 says.
    const double n = 1.0 - (1.0 - particles.initial_porosity[p]) / J;
    particles.porosity[p] = std::clamp(n, 0.0, porous->max_porosity);
    particles.permeability[p] = permeability(*porous, particles.porosity[p]);
  }

  MaterialState state;
  state.stress = from_voigt(particles.stress[p]);
  state.plastic_strain = particles.plastic_strain[p];
  state.damage = particles.damage[p];
  state.internal = particles.internal[p];
  Deformation deformation;
  deformation.dt = dt;
  deformation.deformation_gradient = embed<Dim>(F_new, 1.0);
  const Tensor strain_increment = embed<Dim>(strain, 0.0);
  double work = 0.0;
  const auto update_and_measure = [&] {
    const Tensor before = state.stress;
    material.update(deformation, state);
    work = 0.5 * particles.volume[p] *
           (before + state.stress).cwiseProduct(deformation.strain_increment).sum();
  };
  if (material.is_hyperelastic()) {
    deformation.strain_increment = strain_increment;
    update_and_measure();
  } else if (material.objective_rate() == ObjectiveRate::jaumann) {
    rotate_by_jaumann<Dim>(spin, state.stress);
    deformation.strain_increment = strain_increment;
    update_and_measure();
  } else {
    // Tran et al., MPMICE, eqs. 11-14: work in the unrotated frame.
    const Tensor R_old = polar_rotation<Dim>(F_old);
    const Tensor R_new = polar_rotation<Dim>(F_new);
    state.stress = R_old.transpose() * state.stress * R_old;
    deformation.strain_increment = R_new.transpose() * strain_increment * R_new;
    update_and_measure();
    state.stress = R_new * state.stress * R_new.transpose();
  }
  particles.stress[p] = to_voigt(state.stress);
  particles.plastic_strain[p] = state.plastic_strain;
  particles.damage[p] = state.damage;
  particles.internal[p] = state.internal;
  return work;
}

}  // namespace mpm::detail

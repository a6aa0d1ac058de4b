#include "mpm/material/mohr_coulomb.hpp"

#include <Eigen/Eigenvalues>

#include "mpm/material/material_parameters.hpp"

namespace mpm {

namespace {

// Principal stresses sorted sigma_1 >= sigma_2 >= sigma_3 with their directions.
struct PrincipalStress {
  Vec3d values;
  Tensor directions;  // column i belongs to values[i]
};

PrincipalStress principal_stress(const Tensor& stress) {
  Eigen::SelfAdjointEigenSolver<Tensor> eigen;
  eigen.computeDirect(stress);
  const Vec3d ascending = eigen.eigenvalues();
  Tensor directions;
  for (int i = 0; i < 3; ++i) directions.col(i) = eigen.eigenvectors().col(2 - i);
  return {ascending.reverse(), directions};
}

}  // namespace

cosim::config::Schema MohrCoulomb::schema() {
  auto schema =
      material_parameters::base_schema(std::string(name),
                                       "Non-associated Mohr-Coulomb elastoplasticity (Tran et al., "
                                       "MPMICE, eq. 16) with tension cut-off, friction "
                                       "softening, constant or Rowe dilatancy and optional "
                                       "cohesion degradation; corner-aware return in principal "
                                       "stress space.");
  return FrictionalParameters::add_keys(schema);
}

std::unique_ptr<Material> MohrCoulomb::make(const cosim::config::Node& parameters) {
  return std::make_unique<MohrCoulomb>(material_parameters::read_common_properties(parameters),
                                       material_parameters::read_objective_rate(parameters),
                                       FrictionalParameters::read(parameters));
}

MohrCoulomb::MohrCoulomb(CommonProperties common, ObjectiveRate rate,
                         FrictionalParameters parameters)
    : Material(common, rate), parameters_(std::move(parameters)) {
  if (parameters_.friction.softening_rate() == 0.0 && !parameters_.degradation.enabled())
    fixed_surface_ = surface(MaterialState{});
}

MohrCoulombSurface MohrCoulomb::surface(const MaterialState& state) const {
  if (fixed_surface_) return *fixed_surface_;
  const double phi = parameters_.friction.friction_angle(state.plastic_strain);
  return MohrCoulombSurface::from_angles(phi, parameters_.friction.dilation_angle(phi),
                                         parameters_.cohesion_at(state),
                                         parameters_.tensile_strength_at(state));
}

void MohrCoulomb::update(const Deformation& deformation, MaterialState& state) const {
  const Tensor trial =
      state.stress + parameters_.elastic.stress_increment(deformation.strain_increment);
  state.stress = trial;
  const MohrCoulombSurface yield_surface = surface(state);
  if (yield_surface.surely_inside(trial)) return;
  const PrincipalStress principal = principal_stress(trial);
  const PrincipalReturn result =
      mohr_coulomb_return(principal.values, yield_surface, parameters_.elastic);
  if (result.active == 0) return;
  // Subtracting the correction, rather than rebuilding the stress from its
  // principal values, keeps the error of the eigenvectors out of the elastic part.
  const Tensor& V = principal.directions;
  const Tensor correction = V * (principal.values - result.stress).asDiagonal() * V.transpose();
  state.stress = trial - correction;
  parameters_.record_plastic_step(correction, deformation.strain_increment.trace(), state);
}

double MohrCoulomb::yield_function(const MaterialState& state) const {
  return surface(state).yield(principal_stress(state.stress).values);
}

double MohrCoulomb::friction_angle(const MaterialState& state) const {
  return parameters_.friction.friction_angle(state.plastic_strain);
}

}  // namespace mpm

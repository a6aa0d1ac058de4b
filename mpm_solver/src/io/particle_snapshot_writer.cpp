#include "mpm/io/particle_snapshot_writer.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace mpm {

namespace {

template <int Dim>
cosim::Mesh point_cloud(const Particles<Dim>& particles) {
  cosim::PointCloud cloud;
  cloud.dim = Dim;
  cloud.positions.reserve(particles.size() * Dim);
  for (const auto& x : particles.position)
    for (int d = 0; d < Dim; ++d) cloud.positions.push_back(x[d]);
  cloud.volumes = particles.volume;
  return cosim::Mesh{"particles", std::move(cloud)};
}

void append(std::vector<double>& out, const Voigt& v) {
  out.insert(out.end(), v.begin(), v.end());
}

template <int Dim>
void append(std::vector<double>& out, const Vec<Dim>& v) {
  for (int d = 0; d < Dim; ++d) out.push_back(v[d]);
}

}  // namespace

Tensor logarithmic_strain(const Tensor& deformation_gradient) {
  const Tensor b = deformation_gradient * deformation_gradient.transpose();
  const Eigen::SelfAdjointEigenSolver<Tensor> eigen(b);
  const Eigen::Vector3d ln_lambda = eigen.eigenvalues().array().log().matrix();
  return 0.5 * eigen.eigenvectors() * ln_lambda.asDiagonal() * eigen.eigenvectors().transpose();
}

template <int Dim>
ParticleSnapshotWriter<Dim>::ParticleSnapshotWriter(const std::filesystem::path& directory,
                                                    const Solver<Dim>& solver)
    : initial_position_(solver.particles().position),
      writer_(directory, "particles", point_cloud(solver.particles())) {}

template <int Dim>
void ParticleSnapshotWriter<Dim>::write(const Solver<Dim>& solver) {
  const Particles<Dim>& p = solver.particles();
  const std::size_t n = p.size();
  for (auto* buffer : {&velocity_, &displacement_, &stress_, &effective_stress_, &strain_, &body_})
    buffer->clear();
  for (std::size_t i = 0; i < n; ++i) {
    append<Dim>(velocity_, p.velocity[i]);
    append<Dim>(displacement_, Vec<Dim>(p.position[i] - initial_position_[i]));
    append(stress_, to_voigt(solver.total_stress(i)));
    append(effective_stress_, p.stress[i]);
    append(strain_, to_voigt(logarithmic_strain(embed<Dim>(p.deformation_gradient[i], 1.0))));
    body_.push_back(static_cast<double>(p.body[i]));
  }
  cosim::SnapshotFields fields{
      {"velocity", {velocity_, Dim, "m/s"}},
      {"displacement", {displacement_, Dim, "m"}},
      {"stress", {stress_, 6, "Pa"}},
      {"effective_stress", {effective_stress_, 6, "Pa"}},
      {"strain", {strain_, 6, "1"}},
      {"body", {body_, 1, "1"}},
      {"mass", {p.mass, 1, Dim == 2 ? "kg/m" : "kg"}},
      {"volume", {p.volume, 1, Dim == 2 ? "m^2" : "m^3"}},
  };
  // Per-particle scalars the solver may leave unallocated.
  const auto scalar = [&](const char* name, const std::vector<double>& values, const char* unit) {
    if (values.size() == n) fields.emplace(name, cosim::FieldView{values, 1, unit});
  };
  scalar("plastic_strain", p.plastic_strain, "1");
  scalar("damage", p.damage, "1");
  scalar("porosity", p.porosity, "1");
  scalar("pore_pressure", p.pore_pressure, "Pa");
  if (solver.conducts_heat()) scalar("temperature", p.temperature, "K");
  writer_.write(solver.time(), point_cloud(p), fields);
}

template class ParticleSnapshotWriter<2>;
template class ParticleSnapshotWriter<3>;

}  // namespace mpm

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

// Every point's seeded position, by id (the decomposed run's ranks hold
// only theirs).
template <int Dim>
std::vector<Vec<Dim>> seeded_positions(const CaseDescription& description) {
  std::vector<Vec<Dim>> positions;
  for (const BodySpec& body : description.bodies)
    for (const Vec3d& x : body.positions) positions.push_back(x.head<Dim>());
  return positions;
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
    : initial_position_(solver.particles().position) {
  writer_.emplace(directory, "particles", point_cloud(solver.particles()));
}

template <int Dim>
ParticleSnapshotWriter<Dim>::ParticleSnapshotWriter(std::unique_ptr<cosim::PointCloudSink> ranks,
                                                    const Solver<Dim>& solver)
    : initial_position_(seeded_positions<Dim>(solver.description())), ranks_(std::move(ranks)) {}

template <int Dim>
void ParticleSnapshotWriter<Dim>::write(const Solver<Dim>& solver) {
  hold(solver);
  write_held();
}

template <int Dim>
void ParticleSnapshotWriter<Dim>::hold(const Solver<Dim>& solver) {
  if (held_ == snapshots_.size()) snapshots_.emplace_back();
  take(solver, snapshots_[held_]);
  ++held_;
}

template <int Dim>
void ParticleSnapshotWriter<Dim>::write_held() {
  for (std::size_t k = 0; k < held_; ++k) write(snapshots_[k]);
  held_ = 0;
}

template <int Dim>
void ParticleSnapshotWriter<Dim>::take(const Solver<Dim>& solver, Snapshot& snapshot) const {
  const Particles<Dim>& p = solver.particles();
  const std::size_t n = p.size();
  snapshot.time = solver.time();
  snapshot.id = p.id;
  snapshot.position.clear();
  for (const auto& x : p.position) append<Dim>(snapshot.position, x);
  snapshot.volume = p.volume;
  snapshot.field_count = 0;
  // The next field's values, emptied; valid until the next call.
  const auto field = [&](const char* name, int components, const char* unit) -> auto& {
    if (snapshot.field_count == snapshot.fields.size()) snapshot.fields.emplace_back();
    Field& f = snapshot.fields[snapshot.field_count++];
    f.name = name;
    f.components = components;
    f.unit = unit;
    f.values.clear();
    return f.values;
  };
  auto& velocity = field("velocity", Dim, "m/s");
  for (std::size_t i = 0; i < n; ++i) append<Dim>(velocity, p.velocity[i]);
  auto& displacement = field("displacement", Dim, "m");
  for (std::size_t i = 0; i < n; ++i)
    append<Dim>(displacement, Vec<Dim>(p.position[i] - initial_position_[p.id[i]]));
  auto& stress = field("stress", 6, "Pa");
  for (std::size_t i = 0; i < n; ++i) append(stress, to_voigt(solver.total_stress(i)));
  auto& effective_stress = field("effective_stress", 6, "Pa");
  for (std::size_t i = 0; i < n; ++i) append(effective_stress, p.stress[i]);
  auto& strain = field("strain", 6, "1");
  for (std::size_t i = 0; i < n; ++i)
    append(strain, to_voigt(logarithmic_strain(embed<Dim>(p.deformation_gradient[i], 1.0))));
  auto& body = field("body", 1, "1");
  for (std::size_t i = 0; i < n; ++i) body.push_back(static_cast<double>(p.body[i]));
  field("mass", 1, Dim == 2 ? "kg/m" : "kg") = p.mass;
  field("volume", 1, Dim == 2 ? "m^2" : "m^3") = p.volume;
  // Per-particle scalars the solver may leave unallocated.
  const auto scalar = [&](const char* name, const std::vector<double>& values, const char* unit) {
    if (values.size() == n) field(name, 1, unit) = values;
  };
  scalar("plastic_strain", p.plastic_strain, "1");
  scalar("damage", p.damage, "1");
  scalar("porosity", p.porosity, "1");
  scalar("pore_pressure", p.pore_pressure, "Pa");
  if (solver.conducts_heat()) scalar("temperature", p.temperature, "K");
}

template <int Dim>
void ParticleSnapshotWriter<Dim>::write(const Snapshot& snapshot) {
  if (ranks_) {
    cosim::SnapshotFields fields;
    for (std::size_t k = 0; k < snapshot.field_count; ++k) {
      const Field& f = snapshot.fields[k];
      fields.emplace(f.name, cosim::FieldView{f.values, f.components, f.unit});
    }
    ranks_->write(snapshot.time, snapshot.id, snapshot.position, fields);
    return;
  }
  cosim::PointCloud cloud;
  cloud.dim = Dim;
  cloud.positions = snapshot.position;
  cloud.volumes = snapshot.volume;
  cosim::SnapshotFields fields;
  for (std::size_t k = 0; k < snapshot.field_count; ++k) {
    const Field& f = snapshot.fields[k];
    fields.emplace(f.name, cosim::FieldView{f.values, f.components, f.unit});
  }
  writer_->write(snapshot.time, cosim::Mesh{"particles", std::move(cloud)}, fields);
}

template class ParticleSnapshotWriter<2>;
template class ParticleSnapshotWriter<3>;

}  // namespace mpm

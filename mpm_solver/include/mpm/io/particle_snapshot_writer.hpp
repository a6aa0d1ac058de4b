#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "mpm/solver/solver.hpp"

namespace mpm {

// Particle snapshots as HDF5 + XDMF (`<dir>/particles.xdmf`, a point cloud
// that moves with the particles). Fields per particle:
//   velocity [m/s], displacement [m] (from the positions at construction),
//   stress [Pa] (total sigma' - p I, Tensor6 xx yy zz xy yz xz, tension
//   positive), effective_stress [Pa] (sigma', Tensor6), strain [-]
//   (logarithmic (Hencky) strain 1/2 ln(F F^T), Tensor6; plane strain
//   F_zz = 1), plastic_strain [-], damage [-], porosity [-],
//   pore_pressure [Pa], mass [kg], volume [m^3], body (index).
// In 2D, mass and volume are per unit depth.
template <int Dim>
class ParticleSnapshotWriter {
 public:
  ParticleSnapshotWriter(const std::filesystem::path& directory, const Solver<Dim>& solver);

  void write(const Solver<Dim>& solver);

  std::size_t snapshots_written() const { return writer_.snapshots_written(); }
  std::filesystem::path index_path() const { return writer_.index_path(); }

 private:
  std::vector<Vec<Dim>> initial_position_;
  cosim::SnapshotWriter writer_;
  // Buffers reused between snapshots.
  std::vector<double> velocity_, displacement_, stress_, effective_stress_, strain_, body_;
};

// Hencky strain 1/2 ln(F F^T) of a deformation gradient (3 x 3, det F > 0).
Tensor logarithmic_strain(const Tensor& deformation_gradient);

extern template class ParticleSnapshotWriter<2>;
extern template class ParticleSnapshotWriter<3>;

}  // namespace mpm

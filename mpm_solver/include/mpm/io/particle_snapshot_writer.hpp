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

  // A snapshot taken now and kept in memory until write_held() writes it,
  // or drop_held() forgets it (the outputs of a coupling window that may
  // run again). Snapshots are written in the order they were held; their
  // buffers are kept for the next ones.
  void hold(const Solver<Dim>& solver);
  void write_held();
  void drop_held() { held_ = 0; }
  std::size_t held() const { return held_; }

  std::size_t snapshots_written() const { return writer_.snapshots_written(); }
  std::filesystem::path index_path() const { return writer_.index_path(); }

 private:
  // What one snapshot writes: the point cloud and its fields, element-major.
  struct Field {
    const char* name = "";
    int components = 1;
    const char* unit = "";
    std::vector<double> values;
  };
  struct Snapshot {
    double time = 0.0;
    std::vector<double> position;
    std::vector<double> volume;
    std::vector<Field> fields;  // the first field_count are this snapshot's
    std::size_t field_count = 0;
  };
  void take(const Solver<Dim>& solver, Snapshot& snapshot) const;
  void write(const Snapshot& snapshot);

  std::vector<Vec<Dim>> initial_position_;
  cosim::SnapshotWriter writer_;
  std::vector<Snapshot> snapshots_;  // the first held_ are held
  std::size_t held_ = 0;
};

// Hencky strain 1/2 ln(F F^T) of a deformation gradient (3 x 3, det F > 0).
Tensor logarithmic_strain(const Tensor& deformation_gradient);

extern template class ParticleSnapshotWriter<2>;
extern template class ParticleSnapshotWriter<3>;

}  // namespace mpm

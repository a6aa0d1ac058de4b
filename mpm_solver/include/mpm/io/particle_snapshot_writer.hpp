#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
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
// In 2D, mass and volume are per unit depth. On a rank of a decomposed run
// (issue 27) each snapshot's file is written by all ranks together, each
// its points at their ids' rows: the files of one process.
template <int Dim>
class ParticleSnapshotWriter {
 public:
  ParticleSnapshotWriter(const std::filesystem::path& directory, const Solver<Dim>& solver);
  // The snapshots of a decomposed run, written through `ranks` (a
  // cosim::PartitionedPointCloudWriter).
  ParticleSnapshotWriter(std::unique_ptr<cosim::PointCloudSink> ranks, const Solver<Dim>& solver);

  void write(const Solver<Dim>& solver);

  // A snapshot taken now and kept in memory until write_held() writes it,
  // or drop_held() forgets it (the outputs of a coupling window that may
  // run again). Snapshots are written in the order they were held; their
  // buffers are kept for the next ones.
  void hold(const Solver<Dim>& solver);
  void write_held();
  void drop_held() { held_ = 0; }
  std::size_t held() const { return held_; }

  std::size_t snapshots_written() const {
    return writer_ ? writer_->snapshots_written() : ranks_->snapshots_written();
  }

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
    std::vector<std::uint64_t> id;
    std::vector<double> position;
    std::vector<double> volume;
    std::vector<Field> fields;  // the first field_count are this snapshot's
    std::size_t field_count = 0;
  };
  void take(const Solver<Dim>& solver, Snapshot& snapshot) const;
  void write(const Snapshot& snapshot);

  std::vector<Vec<Dim>> initial_position_;  // by id
  std::optional<cosim::SnapshotWriter> writer_;
  std::unique_ptr<cosim::PointCloudSink> ranks_;
  std::vector<Snapshot> snapshots_;  // the first held_ are held
  std::size_t held_ = 0;
};

// Hencky strain 1/2 ln(F F^T) of a deformation gradient (3 x 3, det F > 0).
Tensor logarithmic_strain(const Tensor& deformation_gradient);

extern template class ParticleSnapshotWriter<2>;
extern template class ParticleSnapshotWriter<3>;

}  // namespace mpm

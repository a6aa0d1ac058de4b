#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "mpm/solver/solver.hpp"

namespace mpm {

// Grid snapshots (`<dir>/grid.xdmf`): the lumped mass [kg] and velocity
// [m/s] of the last step on the grid nodes, summed (mass) and mass-averaged
// (velocity) over the velocity fields of contact.
//
// Only for the linear and GIMP shapes, whose grid values are the nodal
// values of the field. The quadratic B-spline's grid values are control
// points at the Greville abscissae (faces and cell centres, a non-uniform
// set), and a control point is not the field's value there; writing them as
// a node-centred uniform grid would mislabel both position and meaning, so
// supports() is false and the driver skips grid output for it.
template <int Dim>
class GridSnapshotWriter {
 public:
  static bool supports(ShapeKind shape) { return shape != ShapeKind::quadratic_bspline; }

  GridSnapshotWriter(const std::filesystem::path& directory, const Grid<Dim>& grid);
  // On a rank of a decomposed run (issue 27): the rank's owned planes of
  // grid values into `sink`, a writer the ranks share. The planes a rank
  // owns move with the cuts: before each snapshot is written,
  // `select_planes` tells the sink the planes [first, end) (along the last
  // direction, of node_mesh(grid)) the rank owned when it was taken.
  using SelectPlanes = std::function<void(std::array<int, 2> planes)>;
  GridSnapshotWriter(std::unique_ptr<cosim::SnapshotSink> sink, const Grid<Dim>& grid,
                     SelectPlanes select_planes);
  // The whole grid's nodes, as the snapshots give them.
  static cosim::Mesh node_mesh(const Grid<Dim>& grid);
  void write(double time, const Grid<Dim>& grid);

  // A snapshot taken now and kept in memory until write_held() writes it,
  // or drop_held() forgets it (as ParticleSnapshotWriter).
  void hold(double time, const Grid<Dim>& grid);
  void write_held();
  void drop_held() { held_ = 0; }
  std::size_t held() const { return held_; }

  std::size_t snapshots_written() const { return writer_->snapshots_written(); }

 private:
  struct Snapshot {
    double time = 0.0;
    std::array<int, 2> planes{};
    std::vector<double> mass, velocity;
  };

  std::unique_ptr<cosim::SnapshotSink> writer_;
  SelectPlanes select_planes_;       // on ranks
  std::vector<Snapshot> snapshots_;  // the first held_ are held
  std::size_t held_ = 0;
};

extern template class GridSnapshotWriter<2>;
extern template class GridSnapshotWriter<3>;

}  // namespace mpm

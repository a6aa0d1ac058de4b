#include "mpm/io/grid_snapshot_writer.hpp"

#include <fmt/format.h>

#include "cosim/error.hpp"

namespace mpm {

template <int Dim>
cosim::Mesh GridSnapshotWriter<Dim>::node_mesh(const Grid<Dim>& grid) {
  if (!GridSnapshotWriter<Dim>::supports(grid.shape))
    throw cosim::InputError(
        fmt::format("grid snapshots are not available for the {} shape", to_string(grid.shape)));
  cosim::UniformGrid g;
  g.dim = Dim;
  g.location = cosim::GridLocation::node;
  for (int d = 0; d < Dim; ++d) {
    const auto i = static_cast<std::size_t>(d);
    g.origin[i] = grid.origin[d];
    g.spacing[i] = grid.spacing[d];
    g.cells[i] = grid.cells[i];
  }
  return cosim::Mesh{"grid", g};
}

template <int Dim>
GridSnapshotWriter<Dim>::GridSnapshotWriter(const std::filesystem::path& directory,
                                            const Grid<Dim>& grid)
    : writer_(std::make_unique<cosim::SnapshotWriter>(directory, "grid", node_mesh(grid))) {}

template <int Dim>
GridSnapshotWriter<Dim>::GridSnapshotWriter(std::unique_ptr<cosim::SnapshotSink> sink,
                                            const Grid<Dim>& grid, SelectPlanes select_planes)
    : writer_(std::move(sink)), select_planes_(std::move(select_planes)) {
  (void)node_mesh(grid);  // the shape's check
}

template <int Dim>
void GridSnapshotWriter<Dim>::write(double time, const Grid<Dim>& grid) {
  hold(time, grid);
  write_held();
}

// The owned values of the stored planes (all of them on one process).
template <int Dim>
void GridSnapshotWriter<Dim>::hold(double time, const Grid<Dim>& grid) {
  const std::size_t stored = grid.size();
  const std::size_t first = grid.owned_begin();
  const std::size_t n = grid.owned_end() - first;
  if (held_ == snapshots_.size()) snapshots_.emplace_back();
  Snapshot& snapshot = snapshots_[held_++];
  snapshot.time = time;
  snapshot.planes =
      grid.owned_planes == 0
          ? std::array<int, 2>{0, grid.dofs[Dim - 1]}
          : std::array<int, 2>{grid.owned_first_plane, grid.owned_first_plane + grid.owned_planes};
  std::vector<double>& mass = snapshot.mass;
  std::vector<double>& velocity = snapshot.velocity;
  mass.assign(n, 0.0);
  velocity.assign(n * Dim, 0.0);
  const bool stepped = grid.mass.size() >= stored * static_cast<std::size_t>(grid.fields) &&
                       grid.velocity.size() == grid.mass.size();
  if (stepped) {
    for (int f = 0; f < grid.fields; ++f) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(f) * stored + first + i;
        mass[i] += grid.mass[k];
        for (int d = 0; d < Dim; ++d)
          velocity[i * Dim + static_cast<std::size_t>(d)] += grid.mass[k] * grid.velocity[k][d];
      }
    }
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < Dim; ++d)
        if (mass[i] > 0.0) velocity[i * Dim + static_cast<std::size_t>(d)] /= mass[i];
  }
}

template <int Dim>
void GridSnapshotWriter<Dim>::write_held() {
  for (std::size_t k = 0; k < held_; ++k) {
    const Snapshot& s = snapshots_[k];
    if (select_planes_) select_planes_(s.planes);
    writer_->write(s.time, {{"mass", {s.mass, 1, Dim == 2 ? "kg/m" : "kg"}},
                            {"velocity", {s.velocity, Dim, "m/s"}}});
  }
  held_ = 0;
}

template class GridSnapshotWriter<2>;
template class GridSnapshotWriter<3>;

}  // namespace mpm

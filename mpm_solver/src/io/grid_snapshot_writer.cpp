#include "mpm/io/grid_snapshot_writer.hpp"

#include <fmt/format.h>

#include "cosim/error.hpp"

namespace mpm {

namespace {

template <int Dim>
cosim::Mesh node_grid(const Grid<Dim>& grid) {
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

}  // namespace

template <int Dim>
GridSnapshotWriter<Dim>::GridSnapshotWriter(const std::filesystem::path& directory,
                                            const Grid<Dim>& grid)
    : writer_(directory, "grid", node_grid(grid)) {}

template <int Dim>
void GridSnapshotWriter<Dim>::write(double time, const Grid<Dim>& grid) {
  hold(time, grid);
  write_held();
}

template <int Dim>
void GridSnapshotWriter<Dim>::hold(double time, const Grid<Dim>& grid) {
  const std::size_t n = grid.size();
  if (n != writer_.mesh().size())
    throw cosim::Error(
        cosim::ExitCode::internal_error,
        fmt::format("grid has {} values, the node mesh {}", n, writer_.mesh().size()));
  if (held_ == snapshots_.size()) snapshots_.emplace_back();
  Snapshot& snapshot = snapshots_[held_++];
  snapshot.time = time;
  std::vector<double>& mass = snapshot.mass;
  std::vector<double>& velocity = snapshot.velocity;
  mass.assign(n, 0.0);
  velocity.assign(n * Dim, 0.0);
  const bool stepped = grid.mass.size() >= n * static_cast<std::size_t>(grid.fields) &&
                       grid.velocity.size() == grid.mass.size();
  if (stepped) {
    for (int f = 0; f < grid.fields; ++f) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(f) * n + i;
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
    writer_.write(s.time, {{"mass", {s.mass, 1, Dim == 2 ? "kg/m" : "kg"}},
                           {"velocity", {s.velocity, Dim, "m/s"}}});
  }
  held_ = 0;
}

template class GridSnapshotWriter<2>;
template class GridSnapshotWriter<3>;

}  // namespace mpm

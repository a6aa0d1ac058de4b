#include "swe/parallel/gathered_grid_2d.hpp"

#include <array>

#include "cosim/error.hpp"

namespace swe::parallel {

namespace {

[[noreturn]] void read_only(const char* what) {
  throw cosim::Error(
      cosim::ExitCode::internal_error,
      std::string("swe: the gathered grid of a decomposed run is read-only (") + what + ")");
}

}  // namespace

GatheredGrid2d::GatheredGrid2d(MPI_Comm comm,
                               const cosim::decomposition::CartesianDecomposition& decomposition,
                               const Grid2d& grid, const Solver2d& block)
    : comm_(comm), block_(block), grid_(grid) {
  MPI_Comm_rank(comm_, &rank_);
  int offset = 0;
  for (int r = 0; r < decomposition.ranks(); ++r) {
    const cosim::decomposition::Block b = decomposition.block(r);
    blocks_.push_back(b);
    counts_.push_back(static_cast<int>(b.cells[0].size() * b.cells[1].size()));
    displacements_.push_back(offset);
    offset += counts_.back();
  }
  if (rank_ == 0) {
    const std::size_t n = cell_count();
    received_.resize(n);
    for (auto* field : {&h_, &hu_, &hv_, &bed_}) field->resize(n);
  }
}

void GatheredGrid2d::gather() {
  const std::size_t nx = static_cast<std::size_t>(grid_.cells[0]);
  const std::array<std::pair<std::span<const double>, std::vector<double>*>, 4> fields{
      {{block_.depth(), &h_},
       {block_.discharge_x(), &hu_},
       {block_.discharge_y(), &hv_},
       {block_.bed(), &bed_}}};
  for (const auto& [mine, whole] : fields) {
    MPI_Gatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, received_.data(),
                counts_.data(), displacements_.data(), MPI_DOUBLE, 0, comm_);
    if (rank_ != 0) continue;
    for (std::size_t r = 0; r < blocks_.size(); ++r) {
      const auto& b = blocks_[r];
      const double* from = received_.data() + displacements_[r];
      for (auto j = b.cells[1].begin; j < b.cells[1].end; ++j)
        for (auto i = b.cells[0].begin; i < b.cells[0].end; ++i)
          (*whole)[static_cast<std::size_t>(i) + nx * static_cast<std::size_t>(j)] = *from++;
    }
  }
}

std::size_t GatheredGrid2d::cell_count() const {
  return static_cast<std::size_t>(grid_.cells[0]) * static_cast<std::size_t>(grid_.cells[1]);
}
cosim::MeshGeometry GatheredGrid2d::cells() const {
  return cell_mesh(grid_);
}
double GatheredGrid2d::cell_size(std::size_t) const {
  return grid_.spacing[0] * grid_.spacing[1];
}
std::size_t GatheredGrid2d::cell_at(double x, double y) const {
  return swe::cell_at(grid_, x, y);
}

void GatheredGrid2d::set_state(std::span<const double>, std::span<const double>,
                               std::span<const double>) {
  read_only("set_state");
}
void GatheredGrid2d::set_bed(std::span<const double>) {
  read_only("set_bed");
}
double GatheredGrid2d::stable_time_step() const {
  read_only("stable_time_step");
}
void GatheredGrid2d::step(double) {
  read_only("step");
}
void GatheredGrid2d::save_state() {
  read_only("save_state");
}
void GatheredGrid2d::restore_state() {
  read_only("restore_state");
}
void GatheredGrid2d::write_state(cosim::StateFileWriter&) const {
  read_only("write_state");
}
void GatheredGrid2d::read_state(const cosim::StateFileReader&) {
  read_only("read_state");
}

Totals GatheredGrid2d::totals() const {
  // Row sums, then the rows in order, as Solver2d::totals.
  const auto nx = static_cast<std::size_t>(grid_.cells[0]);
  const auto ny = static_cast<std::size_t>(grid_.cells[1]);
  Totals t;
  for (std::size_t j = 0; j < ny && !h_.empty(); ++j) {
    Totals row;
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = i + nx * j;
      row.volume += h_[c];
      row.momentum_x += hu_[c];
      row.momentum_y += hv_[c];
    }
    t.volume += row.volume;
    t.momentum_x += row.momentum_x;
    t.momentum_y += row.momentum_y;
  }
  const double area = cell_size(0);
  return {t.volume * area, t.momentum_x * area, t.momentum_y * area};
}

}  // namespace swe::parallel

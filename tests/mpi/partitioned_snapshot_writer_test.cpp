// The snapshots of a grid decomposed over 1 to 4 ranks (mpirun, label mpi),
// written together with parallel HDF5, against those SnapshotWriter writes
// of the whole grid on one process: the same datasets and attributes bit for
// bit, and the same XDMF index; a field of the wrong size is refused.
#include "cosim/io/partitioned_snapshot_writer.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "cosim/error.hpp"
#include "hdf5_contents.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;

double value(std::int64_t i, std::int64_t j, std::int64_t k, int c, int snapshot) {
  return 1e4 * snapshot + 1e3 * c + 1e2 * static_cast<double>(k) + 10.0 * static_cast<double>(j) +
         static_cast<double>(i) + 0.125;
}

// Values of the cells [begin, end) per direction, x fastest, `components` per cell.
std::vector<double> values_of(const std::array<decomposition::Range, 3>& cells, int components,
                              int snapshot) {
  std::vector<double> values;
  for (auto k = cells[2].begin; k < cells[2].end; ++k)
    for (auto j = cells[1].begin; j < cells[1].end; ++j)
      for (auto i = cells[0].begin; i < cells[0].end; ++i)
        for (int c = 0; c < components; ++c) values.push_back(value(i, j, k, c, snapshot));
  return values;
}

// `counts` values per direction (cells, or nodes for a node grid). The
// first snapshot is written by the blocks of a Cartesian decomposition, the
// second by slabs along the last direction in reverse rank order
// (set_block: cuts that moved).
std::array<decomposition::Range, 3> whole_of(const std::array<int, 3>& counts) {
  return {decomposition::Range{0, counts[0]}, decomposition::Range{0, counts[1]},
          decomposition::Range{0, counts[2]}};
}

void check_against_one_process(int dim, std::array<int, 3> counts_per_direction,
                               const std::string& name,
                               GridLocation location = GridLocation::cell) {
  const std::array<int, 3>& cells = counts_per_direction;
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  fs::path dir;
  // one directory per rank count: ctest may run the counts side by side
  if (rank == 0)
    dir = testing::fresh_directory("partitioned_snapshots_" + name + "_" + std::to_string(ranks));
  std::string text = dir.string();
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  dir = text;

  UniformGrid grid;
  grid.dim = dim;
  grid.origin = {-1.0, 0.5, 2.0};
  grid.spacing = {0.5, 0.25, 0.125};
  const int node = location == GridLocation::node ? 1 : 0;
  grid.cells = {cells[0] - node, dim > 1 ? cells[1] - node : 1, dim > 2 ? cells[2] - node : 1};
  grid.location = location;
  const Mesh mesh{"cells", grid};
  std::array<std::int64_t, 3> counts{cells[0], cells[1], cells[2]};
  const auto dims =
      decomposition::process_grid(ranks, std::span<const std::int64_t>(counts.data(), dim));
  const decomposition::CartesianDecomposition decomposition(dim, counts, dims);
  const decomposition::Block block = decomposition.block(rank);

  PartitionedSnapshotWriter together(MPI_COMM_WORLD, dir / "together", "s", mesh, block.cells);
  const std::array<decomposition::Range, 3> whole = whole_of(cells);
  std::array<decomposition::Range, 3> slab = whole_of(cells);
  slab[static_cast<std::size_t>(dim - 1)] =
      decomposition::even_range(cells[static_cast<std::size_t>(dim - 1)], ranks, ranks - 1 - rank);
  for (int snapshot = 0; snapshot < 2; ++snapshot) {
    const auto& mine = snapshot == 0 ? block.cells : slab;
    if (snapshot == 1) together.set_block(slab);
    const std::vector<double> depth = values_of(mine, 1, snapshot);
    const std::vector<double> velocity = values_of(mine, dim, snapshot);
    const std::vector<double> stress = values_of(mine, 6, snapshot);
    together.write(0.5 * snapshot, {{"depth", {depth, 1, "m"}},
                                    {"velocity", {velocity, dim, "m/s"}},
                                    {"stress", {stress, 6, "Pa"}}});
  }
  EXPECT_EQ(together.snapshots_written(), 2u);
  const std::vector<double> too_few(3, 0.0);
  EXPECT_THROW(together.write(1.0, {{"depth", {too_few, 1}}}), InputError);

  if (rank != 0) return;
  SnapshotWriter alone(dir / "alone", "s", mesh);
  for (int snapshot = 0; snapshot < 2; ++snapshot) {
    const std::vector<double> depth = values_of(whole, 1, snapshot);
    const std::vector<double> velocity = values_of(whole, dim, snapshot);
    const std::vector<double> stress = values_of(whole, 6, snapshot);
    alone.write(0.5 * snapshot, {{"depth", {depth, 1, "m"}},
                                 {"velocity", {velocity, dim, "m/s"}},
                                 {"stress", {stress, 6, "Pa"}}});
  }
  for (const char* file : {"s_000000.h5", "s_000001.h5"})
    EXPECT_EQ(testing::hdf5_contents(dir / "together" / file),
              testing::hdf5_contents(dir / "alone" / file))
        << file << " on " << ranks << " ranks";
  EXPECT_EQ(testing::read_text(dir / "together" / "s.xdmf"),
            testing::read_text(dir / "alone" / "s.xdmf"));
  EXPECT_FALSE(fs::exists(dir / "together" / ".s_000002.h5.tmp"));
}

TEST(PartitionedSnapshotWriter, WritesTheFilesOfOneProcessIn2D) {
  check_against_one_process(2, {13, 9, 1}, "2d");
}

TEST(PartitionedSnapshotWriter, WritesTheFilesOfOneProcessIn3D) {
  check_against_one_process(3, {7, 6, 5}, "3d");
}

// The node values of a grid (a decomposed MPM's grid snapshots).
TEST(PartitionedSnapshotWriter, WritesTheFilesOfOneProcessForGridNodes) {
  check_against_one_process(2, {13, 9, 1}, "nodes_2d", GridLocation::node);
  check_against_one_process(3, {5, 4, 6}, "nodes_3d", GridLocation::node);
}

// The directory rank 0 made, on every rank.
fs::path shared_directory(const std::string& name) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::string text;
  if (rank == 0) text = testing::fresh_directory(name).string();
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
}

// A moving cloud of 50 points whose rows are dealt to the ranks in runs of
// 3, none to the last of several ranks, 2 snapshots of fields of 1, dim
// and 6 components, against SnapshotWriter's of the whole cloud.
void check_point_cloud_against_one_process(int dim) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const fs::path dir =
      shared_directory("partitioned_cloud_" + std::to_string(dim) + "d_" + std::to_string(ranks));
  constexpr std::size_t points = 50;
  const int holding = std::max(1, ranks - 1);
  const auto owner = [&](std::size_t row) { return static_cast<int>((row / 3) % 4) % holding; };
  const auto fill = [&](bool all, int snapshot, std::vector<std::uint64_t>& rows,
                        std::vector<double>& x, std::vector<double>& scalar,
                        std::vector<double>& vector, std::vector<double>& tensor) {
    for (std::size_t row = 0; row < points; ++row) {
      if (!all && owner(row) != rank) continue;
      rows.push_back(row);
      for (int c = 0; c < dim; ++c)
        x.push_back(value(static_cast<std::int64_t>(row), 0, 0, c, snapshot));
      scalar.push_back(value(static_cast<std::int64_t>(row), 1, 0, 0, snapshot));
      for (int c = 0; c < dim; ++c)
        vector.push_back(value(static_cast<std::int64_t>(row), 2, 0, c, snapshot));
      for (int c = 0; c < 6; ++c)
        tensor.push_back(value(static_cast<std::int64_t>(row), 3, 0, c, snapshot));
    }
  };
  PartitionedPointCloudWriter together(MPI_COMM_WORLD, dir / "together", "p", "particles", dim,
                                       points);
  for (int snapshot = 0; snapshot < 2; ++snapshot) {
    std::vector<std::uint64_t> rows;
    std::vector<double> x, mass, velocity, stress;
    fill(false, snapshot, rows, x, mass, velocity, stress);
    together.write(0.25 * snapshot, rows, x,
                   {{"mass", {mass, 1, "kg"}},
                    {"velocity", {velocity, dim, "m/s"}},
                    {"stress", {stress, 6, "Pa"}}});
  }
  EXPECT_EQ(together.snapshots_written(), 2u);
  if (rank != 0) return;
  std::vector<std::uint64_t> rows;
  std::vector<double> x0, m0, v0, s0;
  fill(true, 0, rows, x0, m0, v0, s0);
  const auto cloud = [&](const std::vector<double>& x) {
    PointCloud c;
    c.dim = dim;
    c.positions = x;
    c.volumes.assign(points, 1.0);
    return Mesh{"particles", std::move(c)};
  };
  SnapshotWriter alone(dir / "alone", "p", cloud(x0));
  for (int snapshot = 0; snapshot < 2; ++snapshot) {
    std::vector<double> x, mass, velocity, stress;
    rows.clear();
    fill(true, snapshot, rows, x, mass, velocity, stress);
    alone.write(0.25 * snapshot, cloud(x),
                {{"mass", {mass, 1, "kg"}},
                 {"velocity", {velocity, dim, "m/s"}},
                 {"stress", {stress, 6, "Pa"}}});
  }
  for (const char* file : {"p_000000.h5", "p_000001.h5"})
    EXPECT_EQ(testing::hdf5_contents(dir / "together" / file),
              testing::hdf5_contents(dir / "alone" / file))
        << file << " on " << ranks << " ranks";
  EXPECT_EQ(testing::read_text(dir / "together" / "p.xdmf"),
            testing::read_text(dir / "alone" / "p.xdmf"));
}

TEST(PartitionedPointCloudWriter, WritesTheFilesOfOneProcessIn2D) {
  check_point_cloud_against_one_process(2);
}

TEST(PartitionedPointCloudWriter, WritesTheFilesOfOneProcessIn3D) {
  check_point_cloud_against_one_process(3);
}

// A 2D grid of n x n unit cells with values at `location`, and its whole range.
std::pair<UniformGrid, std::array<decomposition::Range, 3>> square_grid(std::int64_t n,
                                                                        GridLocation location) {
  UniformGrid grid;
  grid.dim = 2;
  grid.cells = {n, n, 1};
  grid.location = location;
  return {grid,
          {decomposition::Range{0, n}, decomposition::Range{0, n}, decomposition::Range{0, 1}}};
}

// Ranks that name different files are refused together, before MPI-IO
// could wait on them; one rank alone names one file.
TEST(PartitionedSnapshotWriter, RefusesRanksThatNameDifferentFiles) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const auto [grid, whole] = square_grid(8, GridLocation::cell);
  const fs::path mine = testing::fresh_directory("partitioned_names_" + std::to_string(ranks) +
                                                 "_" + std::to_string(rank));
  const Mesh mesh{"cells", grid};
  if (ranks == 1) {
    PartitionedSnapshotWriter alone(MPI_COMM_WORLD, mine, "s", mesh, whole);
    EXPECT_EQ(alone.snapshots_written(), 0u);
  } else {
    EXPECT_THROW(PartitionedSnapshotWriter(MPI_COMM_WORLD, mine, "s", mesh, whole), InputError);
  }
}

TEST(PartitionedSnapshotWriter, RefusesAMeshThatIsNotAGridAndABlockOutsideIt) {
  const auto [cells, block] = square_grid(4, GridLocation::cell);
  UniformGrid line = cells;
  line.dim = 1;
  EXPECT_THROW(PartitionedSnapshotWriter(MPI_COMM_WORLD, "never_made", "s", {"line", line}, block),
               InputError);
  auto outside = block;
  outside[0].end = 6;
  EXPECT_THROW(
      PartitionedSnapshotWriter(MPI_COMM_WORLD, "never_made", "s", {"cells", cells}, outside),
      InputError);
  EXPECT_FALSE(fs::exists("never_made"));
}

}  // namespace
}  // namespace cosim

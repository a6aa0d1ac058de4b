#include "checkpoint/mesh_state.hpp"

#include <gtest/gtest.h>

#include "same_bits.hpp"

namespace cosim::checkpoint {
namespace {

namespace fs = std::filesystem;
using cosim::testing::same_bits;

// Every kind of mesh comes back exactly as it was written.
TEST(CheckpointMeshState, EveryKindOfMeshReadsBackBitForBit) {
  const fs::path dir = fs::path(COSIM_BINARY_DIR) / "test_runs" / "checkpoint_mesh_state";
  fs::create_directories(dir);
  UniformGrid grid{.dim = 2,
                   .origin = {0.1, -0.2, 0.0},
                   .spacing = {1.0 / 3.0, 0.25, 1.0},
                   .cells = {7, 5, 1},
                   .location = GridLocation::node};
  const Mesh meshes[] = {{"grid", grid},
                         {"line", NonUniformLine{{0.0, 0.1, 0.35, 1.0 / 7.0 + 1.0}}},
                         {"particles", PointCloud{2, {0.1, 0.2, 0.3, 0.4 + 1e-17}, {1e-3, 2e-3}}},
                         {"cells", CellCloud{3, {0.0, 0.0, 0.0, 1.0, 1.0, 1.0}, {0.5, 0.25}}}};
  {
    StateFileWriter out(dir / "meshes.h5", "test_meshes", 1);
    for (const Mesh& m : meshes) write_mesh(out, "mesh." + m.name, m);
    out.commit();
  }
  const StateFileReader in(dir / "meshes.h5", "test_meshes", 1);
  const Mesh g = read_mesh(in, "mesh.grid", "grid");
  const auto& back = std::get<UniformGrid>(g.geometry);
  EXPECT_EQ(back.dim, 2);
  EXPECT_EQ(back.origin, grid.origin);
  EXPECT_EQ(back.spacing, grid.spacing);
  EXPECT_EQ(back.cells, grid.cells);
  EXPECT_EQ(back.location, GridLocation::node);
  EXPECT_TRUE(same_bits(std::get<NonUniformLine>(read_mesh(in, "mesh.line", "line").geometry).edges,
                        std::get<NonUniformLine>(meshes[1].geometry).edges));
  const auto cloud = std::get<PointCloud>(read_mesh(in, "mesh.particles", "particles").geometry);
  EXPECT_TRUE(same_bits(cloud.positions, std::get<PointCloud>(meshes[2].geometry).positions));
  EXPECT_TRUE(same_bits(cloud.volumes, std::get<PointCloud>(meshes[2].geometry).volumes));
  const auto cells = std::get<CellCloud>(read_mesh(in, "mesh.cells", "cells").geometry);
  EXPECT_EQ(cells.dim, 3);
  EXPECT_TRUE(same_bits(cells.centres, std::get<CellCloud>(meshes[3].geometry).centres));
  EXPECT_EQ(read_mesh(in, "mesh.cells", "cells").name, "cells");
}

}  // namespace
}  // namespace cosim::checkpoint

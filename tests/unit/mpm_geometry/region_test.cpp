// Regions: boxes, polygons and closed triangulated surfaces.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "cosim/error.hpp"
#include "mpm/geometry/box.hpp"
#include "mpm/geometry/polygon.hpp"
#include "mpm/geometry/polyhedron.hpp"

namespace mpm {
namespace {

TEST(Box, IsHalfOpen) {
  const Box<2> box{Vec<2>(0.0, 0.0), Vec<2>(1.0, 2.0)};
  EXPECT_TRUE(box.contains(Vec<2>(0.0, 0.0)));
  EXPECT_TRUE(box.contains(Vec<2>(0.5, 1.999)));
  EXPECT_FALSE(box.contains(Vec<2>(1.0, 0.5)));
  EXPECT_FALSE(box.contains(Vec<2>(0.5, 2.0)));
  EXPECT_FALSE(box.contains(Vec<2>(-1e-12, 0.5)));
  EXPECT_DOUBLE_EQ(box.volume(), 2.0);
  const Box<3> cube{Vec<3>::Zero(), Vec<3>::Ones()};
  EXPECT_TRUE(cube.contains(Vec<3>(0.5, 0.5, 0.0)));
  EXPECT_FALSE(cube.contains(Vec<3>(0.5, 1.0, 0.5)));
}

TEST(Polygon, ContainsConvexAndConcave) {
  const Polygon triangle({Vec<2>(0, 0), Vec<2>(2, 0), Vec<2>(0, 2)});
  EXPECT_TRUE(triangle.contains(Vec<2>(0.5, 0.5)));
  EXPECT_FALSE(triangle.contains(Vec<2>(1.5, 1.5)));
  EXPECT_DOUBLE_EQ(triangle.area(), 2.0);
  // an L shape, clockwise
  const Polygon l_shape(
      {Vec<2>(0, 0), Vec<2>(0, 2), Vec<2>(1, 2), Vec<2>(1, 1), Vec<2>(2, 1), Vec<2>(2, 0)});
  EXPECT_DOUBLE_EQ(l_shape.area(), 3.0);
  EXPECT_TRUE(l_shape.contains(Vec<2>(0.5, 1.5)));
  EXPECT_TRUE(l_shape.contains(Vec<2>(1.5, 0.5)));
  EXPECT_FALSE(l_shape.contains(Vec<2>(1.5, 1.5)));
  EXPECT_FALSE(
      l_shape.contains(Vec<2>(-0.5, 1.0)));  // ray through the vertices (0, ...) edge and (2, 1)
  EXPECT_TRUE(l_shape.contains(Vec<2>(0.5, 1.0)));  // ray through the reflex vertex (1, 1)
  const Box<2>& b = l_shape.bounding_box();
  EXPECT_EQ(b.lower, Vec<2>(0, 0));
  EXPECT_EQ(b.upper, Vec<2>(2, 2));
}

// Two triangles that split a square along its diagonal: every point of the
// square's lattice, including those on the diagonal and the vertices, is
// claimed by at most one; inside the square by exactly one.
TEST(Polygon, NeighboursShareEdgesWithoutOverlap) {
  const Polygon lower({Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(1, 1)});
  const Polygon upper({Vec<2>(0, 0), Vec<2>(1, 1), Vec<2>(0, 1)});
  for (int i = -2; i <= 10; ++i) {
    for (int j = -2; j <= 10; ++j) {
      const Vec<2> x(i / 8.0, j / 8.0);
      const int claims = int{lower.contains(x)} + int{upper.contains(x)};
      const bool strictly_inside = i > 0 && i < 8 && j > 0 && j < 8;
      const bool outside = i < 0 || i > 8 || j < 0 || j > 8;
      if (strictly_inside) {
        EXPECT_EQ(claims, 1) << x.transpose();
      }
      if (outside) {
        EXPECT_EQ(claims, 0) << x.transpose();
      }
      EXPECT_LE(claims, 1) << x.transpose();
    }
  }
}

TEST(Polygon, RejectsBadInput) {
  EXPECT_THROW(Polygon({Vec<2>(0, 0), Vec<2>(1, 0)}), cosim::InputError);
  EXPECT_THROW(Polygon({Vec<2>(0, 0), Vec<2>(1, 1), Vec<2>(2, 2)}), cosim::InputError);
}

// A cube [0, 1]^3 with each face split into n x n squares of two triangles,
// outward oriented.
Polyhedron subdivided_cube(int n) {
  std::vector<Vec<3>> vertices;
  std::vector<std::array<int, 3>> triangles;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int base = static_cast<int>(vertices.size());
      for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
          Vec<3> p;
          p[axis] = side;
          p[u] = static_cast<double>(i) / n;
          p[v] = static_cast<double>(j) / n;
          vertices.push_back(p);
        }
      }
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
          // u x v = +axis: counter-clockwise in (u, v) faces outward on side 1
          if (side == 1) {
            triangles.push_back({a, b, d});
            triangles.push_back({a, d, c});
          } else {
            triangles.push_back({a, d, b});
            triangles.push_back({a, c, d});
          }
        }
      }
    }
  }
  // merge the duplicated edge vertices so the surface is closed
  std::vector<int> id(vertices.size());
  std::vector<Vec<3>> unique;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    id[k] = -1;
    for (std::size_t m = 0; m < unique.size(); ++m)
      if ((unique[m] - vertices[k]).norm() < 1e-12) id[k] = static_cast<int>(m);
    if (id[k] < 0) {
      id[k] = static_cast<int>(unique.size());
      unique.push_back(vertices[k]);
    }
  }
  for (auto& t : triangles)
    for (int& v : t) v = id[static_cast<std::size_t>(v)];
  return Polyhedron(unique, triangles);
}

TEST(Polyhedron, UnitCubeContainsItsInteriorIncludingRaysThroughEdgesAndVertices) {
  for (int n : {1, 4}) {
    const Polyhedron cube = subdivided_cube(n);
    EXPECT_NEAR(cube.volume(), 1.0, 1e-14);
    // lattice points: rays along x through triangle edges and mesh vertices
    for (int i = -1; i <= 9; ++i) {
      for (int j = -1; j <= 9; ++j) {
        for (int k = -1; k <= 9; ++k) {
          const Vec<3> x(i / 8.0, j / 8.0, k / 8.0);
          const bool on_surface = (x.array() == 0.0 || x.array() == 1.0).any() &&
                                  (x.array() >= 0.0).all() && (x.array() <= 1.0).all();
          if (on_surface) continue;
          const bool inside = (x.array() > 0.0).all() && (x.array() < 1.0).all();
          EXPECT_EQ(cube.contains(x), inside) << "n " << n << " x " << x.transpose();
        }
      }
    }
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (int p = 0; p < 2000; ++p) {
      const Vec<3> x(u(rng), u(rng), u(rng));
      EXPECT_EQ(cube.contains(x), (x.array() > 0.0).all() && (x.array() < 1.0).all())
          << x.transpose();
    }
  }
}

TEST(Polyhedron, TetrahedronMatchesBarycentricTest) {
  const std::vector<Vec<3>> v{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
  // inward orientation works as well
  const Polyhedron tet(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
  EXPECT_NEAR(tet.volume(), 1.0 / 6.0, 1e-15);
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  int inside_count = 0;
  for (int p = 0; p < 5000; ++p) {
    const Vec<3> x(u(rng), u(rng), u(rng));
    const bool inside = x.x() > 0 && x.y() > 0 && x.z() > 0 && x.sum() < 1;
    EXPECT_EQ(tet.contains(x), inside) << x.transpose();
    inside_count += inside;
  }
  EXPECT_GT(inside_count, 100);
  EXPECT_TRUE(tet.contains(Vec<3>(0.25, 0.25, 0.25)));
  EXPECT_FALSE(
      tet.contains(Vec<3>(-0.5, 0.25, 0.25)));         // ray through the tetrahedron: two crossings
  EXPECT_FALSE(tet.contains(Vec<3>(-0.5, 0.0, 0.0)));  // ray along an edge
}

TEST(Polyhedron, RejectsOpenOrInconsistentSurfaces) {
  const std::vector<Vec<3>> v{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
  EXPECT_THROW(Polyhedron(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}}), cosim::InputError);
  EXPECT_THROW(Polyhedron(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 2, 3}}),
               cosim::InputError);  // flipped face
  EXPECT_THROW(Polyhedron(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 7}}), cosim::InputError);
  EXPECT_THROW(Polyhedron(v, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 3}}), cosim::InputError);
}

}  // namespace
}  // namespace mpm

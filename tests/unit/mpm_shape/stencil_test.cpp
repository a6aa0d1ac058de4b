// Tensor-product stencils in 1D, 2D and 3D and the per-run kernel dispatch.
#include "mpm/shape/stencil.hpp"

#include <gtest/gtest.h>

#include <random>
#include <type_traits>
#include <vector>

#include "mpm/shape/shape_dispatch.hpp"

namespace mpm {
namespace {

template <int Dim>
GridGeometry<Dim> test_grid() {
  GridGeometry<Dim> g;
  for (int d = 0; d < Dim; ++d) {
    g.origin[d] = -1.0 + 0.3 * d;
    g.spacing[d] = 0.25 + 0.1 * d;
    g.cells[d] = 4 + d;
  }
  return g;
}

template <int Dim, class Kernel>
std::size_t value_count(const GridGeometry<Dim>& g) {
  std::size_t n = 1;
  for (int d = 0; d < Dim; ++d) n *= static_cast<std::size_t>(Kernel::dofs(g.cells[d]));
  return n;
}

template <int Dim, class Kernel>
Vec<Dim> value_position(std::size_t flat, const GridGeometry<Dim>& g) {
  Vec<Dim> x;
  for (int d = 0; d < Dim; ++d) {
    const auto n = static_cast<std::size_t>(Kernel::dofs(g.cells[d]));
    x[d] =
        g.origin[d] + g.spacing[d] * Kernel::dof_coordinate(static_cast<int>(flat % n), g.cells[d]);
    flat /= n;
  }
  return x;
}

// Random points in the grid, plus its corners and points on its faces.
template <int Dim>
std::vector<Vec<Dim>> sample_points(const GridGeometry<Dim>& g, int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<Dim>> xs;
  const Vec<Dim> lo = g.origin, hi = g.upper();
  for (int n = 0; n < count; ++n) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = lo[d] + u(rng) * (hi[d] - lo[d]);
    // every fourth point pushed onto a face
    if (n % 4 == 1) x[n % Dim] = (n / 4) % 2 ? hi[n % Dim] : lo[n % Dim];
    xs.push_back(x);
  }
  xs.push_back(lo);
  xs.push_back(hi);
  return xs;
}

template <class T>
class StencilTest : public ::testing::Test {};
template <int D, class K>
struct Case {
  static constexpr int Dim = D;
  using Kernel = K;
};
using Cases = ::testing::Types<Case<1, GimpKernel>, Case<2, LinearKernel>, Case<2, GimpKernel>,
                               Case<2, QuadraticBsplineKernel>, Case<3, LinearKernel>,
                               Case<3, GimpKernel>, Case<3, QuadraticBsplineKernel>>;
TYPED_TEST_SUITE(StencilTest, Cases);

TYPED_TEST(StencilTest, PartitionOfUnityAndLinearReproductionInside) {
  constexpr int Dim = TypeParam::Dim;
  using Kernel = typename TypeParam::Kernel;
  const auto g = test_grid<Dim>();
  const std::size_t n = value_count<Dim, Kernel>(g);
  const Vec<Dim> half = 0.25 * g.spacing;
  for (const Vec<Dim>& x : sample_points(g, 300)) {
    Stencil<Dim, Kernel> s;
    s.evaluate(x, half, g);
    double sum = 0.0;
    int visited = 0;
    Vec<Dim> grad_sum = Vec<Dim>::Zero(), reproduced = Vec<Dim>::Zero();
    Mat<Dim> grad_x = Mat<Dim>::Zero();
    s.for_each([&](std::size_t v, double w, const Vec<Dim>& grad) {
      ASSERT_LT(v, n);
      sum += w;
      grad_sum += grad;
      const Vec<Dim> xv = value_position<Dim, Kernel>(v, g);
      reproduced += w * xv;
      grad_x += xv * grad.transpose();
      ++visited;
    });
    EXPECT_EQ(visited, (Stencil<Dim, Kernel>::size));
    EXPECT_NEAR(sum, 1.0, 1e-13);
    EXPECT_LT(grad_sum.norm(), 1e-11) << x.transpose();
    // GIMP reproduces x only when the particle domain lies inside the grid
    bool clipped = false;
    for (int d = 0; d < Dim; ++d)
      clipped |= x[d] - half[d] < g.origin[d] || x[d] + half[d] > g.upper()[d];
    if (!std::is_same_v<Kernel, GimpKernel> || !clipped) {
      EXPECT_LT((reproduced - x).norm(), 1e-12) << x.transpose();
      EXPECT_LT((grad_x - Mat<Dim>::Identity()).norm(), 1e-11) << x.transpose();
    }
  }
}

TYPED_TEST(StencilTest, GradientsMatchFiniteDifferences) {
  constexpr int Dim = TypeParam::Dim;
  using Kernel = typename TypeParam::Kernel;
  const auto g = test_grid<Dim>();
  const std::size_t n = value_count<Dim, Kernel>(g);
  const Vec<Dim> half = 0.3 * g.spacing;
  auto weights = [&](const Vec<Dim>& x) {
    std::vector<double> w(n, 0.0);
    Stencil<Dim, Kernel> s;
    s.evaluate(x, half, g);
    s.for_each([&](std::size_t v, double wv, const Vec<Dim>&) { w[v] = wv; });
    return w;
  };
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  const double h = 1e-6;
  for (int p = 0; p < 100; ++p) {
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) {
      // keep off the nodes, where the linear hat has a kink
      const double cell = std::floor(u(rng) * g.cells[d]);
      x[d] = g.origin[d] + g.spacing[d] * (cell + u(rng));
    }
    std::vector<Vec<Dim>> grad(n, Vec<Dim>::Zero());
    Stencil<Dim, Kernel> s;
    s.evaluate(x, half, g);
    s.for_each([&](std::size_t v, double, const Vec<Dim>& gv) { grad[v] = gv; });
    for (int d = 0; d < Dim; ++d) {
      Vec<Dim> e = Vec<Dim>::Zero();
      e[d] = h;
      const auto plus = weights(x + e), minus = weights(x - e);
      for (std::size_t v = 0; v < n; ++v)
        EXPECT_NEAR(grad[v][d], (plus[v] - minus[v]) / (2 * h), 1e-6 / g.spacing[d])
            << "x " << x.transpose() << " value " << v << " direction " << d;
    }
  }
}

TEST(ShapeDispatch, PicksTheKernelOfTheRun) {
  auto support = [](ShapeKind kind) {
    return with_kernel<2>(kind, [](auto kernel) { return decltype(kernel)::support; });
  };
  EXPECT_EQ(support(ShapeKind::linear), 2);
  EXPECT_EQ(support(ShapeKind::gimp), 3);
  EXPECT_EQ(support(ShapeKind::quadratic_bspline), 3);
  const int dofs = with_kernel<3>(ShapeKind::quadratic_bspline,
                                  [](auto kernel) { return decltype(kernel)::dofs(5); });
  EXPECT_EQ(dofs, 7);
  EXPECT_EQ(to_string(ShapeKind::quadratic_bspline), "quadratic_bspline");
}

}  // namespace
}  // namespace mpm

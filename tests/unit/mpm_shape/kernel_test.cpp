// One-dimensional shape kernels: partition of unity, linear reproduction,
// the papers' formulas, derivatives and continuity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mpm/shape/gimp_kernel.hpp"
#include "mpm/shape/linear_kernel.hpp"
#include "mpm/shape/quadratic_bspline_kernel.hpp"

namespace mpm {
namespace {

// Weights and derivatives of every grid value at xi.
struct Dense {
  std::vector<double> N, dN;
};

template <class Kernel>
Dense dense(double xi, double lp, int cells) {
  Dense d{std::vector<double>(static_cast<std::size_t>(Kernel::dofs(cells)), 0.0),
          std::vector<double>(static_cast<std::size_t>(Kernel::dofs(cells)), 0.0)};
  double N[Kernel::support], dN[Kernel::support];
  const int first = Kernel::evaluate(xi, lp, cells, N, dN);
  EXPECT_GE(first, 0) << "xi " << xi;
  EXPECT_LE(first + Kernel::support, Kernel::dofs(cells)) << "xi " << xi;
  for (int k = 0; k < Kernel::support; ++k) {
    d.N[static_cast<std::size_t>(first + k)] = N[k];
    d.dN[static_cast<std::size_t>(first + k)] = dN[k];
  }
  return d;
}

// Points in [0, cells]: random ones plus the faces, nodes, cell centres and
// points just inside the faces.
std::vector<double> sample_points(int cells, int random_count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, cells);
  std::vector<double> xs;
  for (int i = 0; i < random_count; ++i) xs.push_back(u(rng));
  for (int k = 0; k <= cells; ++k) {
    xs.push_back(k);
    if (k < cells) xs.push_back(k + 0.5);
  }
  for (double e : {1e-14, 1e-9, 1e-3, 0.1, 0.25, 0.49}) {
    xs.push_back(e);
    xs.push_back(cells - e);
  }
  return xs;
}

constexpr int kCells = 7;

template <class Kernel>
class KernelTest : public ::testing::Test {};
using Kernels = ::testing::Types<LinearKernel, GimpKernel, QuadraticBsplineKernel>;
TYPED_TEST_SUITE(KernelTest, Kernels);

TYPED_TEST(KernelTest, PartitionOfUnityAndZeroGradientSum) {
  using Kernel = TypeParam;
  for (int cells : {2, 3, kCells}) {
    for (double lp : {0.0, 0.125, 0.25, 0.5}) {
      for (double xi : sample_points(cells, 400, 1)) {
        const Dense d = dense<Kernel>(xi, lp, cells);
        double sum = 0.0, dsum = 0.0;
        for (std::size_t i = 0; i < d.N.size(); ++i) {
          EXPECT_GE(d.N[i], -1e-15) << "xi " << xi << " value " << i;
          sum += d.N[i];
          dsum += d.dN[i];
        }
        EXPECT_NEAR(sum, 1.0, 1e-14) << "xi " << xi << " lp " << lp << " cells " << cells;
        EXPECT_NEAR(dsum, 0.0, 1e-12) << "xi " << xi << " lp " << lp << " cells " << cells;
      }
    }
  }
}

TYPED_TEST(KernelTest, FirstAndLastValueSitOnTheFaces) {
  using Kernel = TypeParam;
  EXPECT_EQ(Kernel::dof_coordinate(0, kCells), 0.0);
  EXPECT_EQ(Kernel::dof_coordinate(Kernel::dofs(kCells) - 1, kCells), kCells);
  // and the kernel interpolates there
  EXPECT_NEAR(dense<Kernel>(0.0, 0.0, kCells).N.front(), 1.0, 1e-15);
  EXPECT_NEAR(dense<Kernel>(kCells, 0.0, kCells).N.back(), 1.0, 1e-15);
}

// sum N_i x_i = x and sum dN_i x_i = 1 with the values at dof_coordinate.
// GIMP reproduces the centre of the particle domain, which is x unless the
// domain is clipped at a face.
TYPED_TEST(KernelTest, ReproducesLinearFields) {
  using Kernel = TypeParam;
  for (double lp : {0.0, 0.2, 0.5}) {
    for (double xi : sample_points(kCells, 300, 2)) {
      const Dense d = dense<Kernel>(xi, lp, kCells);
      double x = 0.0, slope = 0.0;
      for (int i = 0; i < Kernel::dofs(kCells); ++i) {
        x += d.N[static_cast<std::size_t>(i)] * Kernel::dof_coordinate(i, kCells);
        slope += d.dN[static_cast<std::size_t>(i)] * Kernel::dof_coordinate(i, kCells);
      }
      const bool clipped = std::is_same_v<Kernel, GimpKernel> && (xi <= lp || xi >= kCells - lp);
      if (clipped) {
        const double centre = 0.5 * (std::max(xi - lp, 0.0) + std::min(xi + lp, double{kCells}));
        EXPECT_NEAR(x, centre, 1e-13) << "xi " << xi << " lp " << lp;
      } else {
        EXPECT_NEAR(x, xi, 1e-13) << "xi " << xi << " lp " << lp;
        EXPECT_NEAR(slope, 1.0, 1e-12) << "xi " << xi << " lp " << lp;
      }
    }
  }
}

TYPED_TEST(KernelTest, DerivativesMatchFiniteDifferences) {
  using Kernel = TypeParam;
  const double lp = 0.3, h = 1e-6;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, kCells);
  int checked = 0;
  for (int n = 0; n < 500; ++n) {
    const double xi = u(rng);
    // stay off the points where a derivative jumps: nodes (linear), and
    // where the clipped GIMP domain starts touching a face
    if (xi - h < 0.0 || xi + h > kCells) continue;
    if (std::is_same_v<Kernel, LinearKernel> && std::abs(xi - std::round(xi)) < 2 * h) continue;
    if (std::is_same_v<Kernel, GimpKernel> &&
        (std::abs(xi - lp) < 2 * h || std::abs(xi - (kCells - lp)) < 2 * h))
      continue;
    const Dense d = dense<Kernel>(xi, lp, kCells), plus = dense<Kernel>(xi + h, lp, kCells),
                minus = dense<Kernel>(xi - h, lp, kCells);
    for (std::size_t i = 0; i < d.N.size(); ++i) {
      const double fd = (plus.N[i] - minus.N[i]) / (2 * h);
      EXPECT_NEAR(d.dN[i], fd, 1e-7) << "xi " << xi << " value " << i;
    }
    ++checked;
  }
  EXPECT_GT(checked, 400);
}

// Values, and for GIMP and the B-spline also derivatives, agree on both
// sides of every cell boundary (C0 for linear, C1 for the others).
TYPED_TEST(KernelTest, ContinuousAcrossCellBoundaries) {
  using Kernel = TypeParam;
  const double e = 1e-10;
  constexpr bool c1 = !std::is_same_v<Kernel, LinearKernel>;
  for (double lp : {0.1, 0.25, 0.5}) {
    // cell boundaries, and for GIMP the breakpoints k +- lp of eq. 11
    std::vector<double> breaks;
    for (int k = 1; k < kCells; ++k) {
      breaks.push_back(k);
      if (k >= 2 && k <= kCells - 2) {
        breaks.push_back(k - lp);
        breaks.push_back(k + lp);
      }
      breaks.push_back(k + 0.5);  // where GIMP's first value changes
    }
    for (double xb : breaks) {
      const Dense left = dense<Kernel>(xb - e, lp, kCells),
                  right = dense<Kernel>(xb + e, lp, kCells);
      for (std::size_t i = 0; i < left.N.size(); ++i) {
        EXPECT_NEAR(left.N[i], right.N[i], 1e-9) << "at " << xb << " value " << i;
        // (a clipped GIMP domain has a kink where it starts touching a face)
        const bool inside = xb - lp > 1e-9 && xb + lp < kCells - 1e-9;
        if (c1 && inside) {
          EXPECT_NEAR(left.dN[i], right.dN[i], 1e-8) << "at " << xb << " value " << i;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// GIMP against the five pieces of Zheng et al., eq. 11 (x = x_mp - x_i, in
// cells, h = 1).

double gimp_eq11(double x, double l) {
  if (x > -1 - l && x <= -1 + l) return (1 + l + x) * (1 + l + x) / (4 * l);
  if (x > -1 + l && x <= -l) return 1 + x;
  if (x > -l && x <= l) return 1 - (x * x + l * l) / (2 * l);
  if (x > l && x <= 1 - l) return 1 - x;
  if (x > 1 - l && x <= 1 + l) return (1 + l - x) * (1 + l - x) / (4 * l);
  return 0.0;
}

TEST(GimpKernel, EqualsZhengEq11InTheInterior) {
  std::mt19937 rng(4);
  for (double lp : {0.05, 0.25, 0.4, 0.5}) {
    std::uniform_real_distribution<double> u(lp, kCells - lp);
    for (int n = 0; n < 300; ++n) {
      const double xi = u(rng);
      const Dense d = dense<GimpKernel>(xi, lp, kCells);
      for (int i = 0; i <= kCells; ++i)
        EXPECT_NEAR(d.N[static_cast<std::size_t>(i)], gimp_eq11(xi - i, lp), 1e-14)
            << "xi " << xi << " node " << i << " lp " << lp;
    }
  }
}

TEST(GimpKernel, TendsToTheLinearHat) {
  for (double xi : sample_points(kCells, 200, 5)) {
    const Dense hat = dense<LinearKernel>(xi, 0.0, kCells);
    const Dense tiny = dense<GimpKernel>(xi, 1e-12, kCells);
    const Dense zero = dense<GimpKernel>(xi, 0.0, kCells);
    for (std::size_t i = 0; i < hat.N.size(); ++i) {
      EXPECT_NEAR(tiny.N[i], hat.N[i], 1e-12) << "xi " << xi;
      EXPECT_NEAR(zero.N[i], hat.N[i], 1e-15) << "xi " << xi;
      EXPECT_DOUBLE_EQ(zero.dN[i], hat.dN[i]) << "xi " << xi;
    }
  }
}

TEST(GimpKernel, ClippedDomainAveragesTheHatsOverThePartInsideTheGrid) {
  // xi = 0.1, l_p = 0.3: domain [0, 0.4]; mean of hat_0 = 1 - 0.2, hat_1 = 0.2
  const Dense d = dense<GimpKernel>(0.1, 0.3, kCells);
  EXPECT_NEAR(d.N[0], 0.8, 1e-15);
  EXPECT_NEAR(d.N[1], 0.2, 1e-15);
  EXPECT_EQ(d.N[2], 0.0);
  // at the last face: domain [cells - 0.5, cells]
  const Dense e = dense<GimpKernel>(kCells, 0.5, kCells);
  EXPECT_NEAR(e.N[kCells], 0.75, 1e-15);
  EXPECT_NEAR(e.N[kCells - 1], 0.25, 1e-15);
}

// ---------------------------------------------------------------------------
// The B-spline against Cox-de Boor (Pan et al. 2021, eqs. 85-87) evaluated
// by recursion on the open knot vector.

std::vector<double> open_knots(int cells) {
  std::vector<double> t{0.0, 0.0};
  for (int k = 0; k <= cells; ++k) t.push_back(k);
  t.push_back(cells);
  t.push_back(cells);
  return t;
}

double cox_de_boor(const std::vector<double>& t, std::size_t i, int p, double x) {
  if (p == 0) {
    // half-open spans, the last one closed, so the basis sums to 1 on [0, cells]
    const bool last_span = t[i + 1] == t.back() && t[i] < t[i + 1];
    return (t[i] <= x && (x < t[i + 1] || (last_span && x == t[i + 1]))) ? 1.0 : 0.0;
  }
  const auto pd = static_cast<std::size_t>(p);
  double value = 0.0;
  if (t[i + pd] > t[i]) value += (x - t[i]) / (t[i + pd] - t[i]) * cox_de_boor(t, i, p - 1, x);
  if (t[i + pd + 1] > t[i + 1])
    value += (t[i + pd + 1] - x) / (t[i + pd + 1] - t[i + 1]) * cox_de_boor(t, i + 1, p - 1, x);
  return value;
}

double cox_de_boor_derivative(const std::vector<double>& t, std::size_t i, int p, double x) {
  const auto pd = static_cast<std::size_t>(p);
  double value = 0.0;
  if (t[i + pd] > t[i]) value += p / (t[i + pd] - t[i]) * cox_de_boor(t, i, p - 1, x);
  if (t[i + pd + 1] > t[i + 1])
    value -= p / (t[i + pd + 1] - t[i + 1]) * cox_de_boor(t, i + 1, p - 1, x);
  return value;
}

TEST(QuadraticBsplineKernel, MatchesCoxDeBoorRecursion) {
  for (int cells : {1, 2, 3, kCells}) {
    const auto t = open_knots(cells);
    ASSERT_EQ(t.size(), static_cast<std::size_t>(QuadraticBsplineKernel::dofs(cells) + 3));
    for (double xi : sample_points(cells, 300, 6)) {
      const Dense d = dense<QuadraticBsplineKernel>(xi, 0.0, cells);
      for (std::size_t i = 0; i < d.N.size(); ++i) {
        EXPECT_NEAR(d.N[i], cox_de_boor(t, i, 2, xi), 1e-14)
            << "cells " << cells << " xi " << xi << " i " << i;
        EXPECT_NEAR(d.dN[i], cox_de_boor_derivative(t, i, 2, xi), 1e-13)
            << "cells " << cells << " xi " << xi << " i " << i;
      }
    }
  }
}

TEST(QuadraticBsplineKernel, GrevilleAbscissae) {
  const std::vector<double> expected{0.0, 0.5, 1.5, 2.5, 3.0};
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(QuadraticBsplineKernel::dof_coordinate(i, 3), expected[static_cast<std::size_t>(i)]);
  const auto t = open_knots(3);
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(QuadraticBsplineKernel::dof_coordinate(static_cast<int>(i), 3),
              0.5 * (t[i + 1] + t[i + 2]));
}

TEST(ShapeKernels, PointsOutsideTheGridAreClampedToTheFace) {
  for (double xi : {-0.5, kCells + 0.3}) {
    const double face = std::clamp(xi, 0.0, double{kCells});
    const Dense a = dense<QuadraticBsplineKernel>(xi, 0.0, kCells),
                b = dense<QuadraticBsplineKernel>(face, 0.0, kCells);
    EXPECT_EQ(a.N, b.N);
    const Dense c = dense<GimpKernel>(xi, 0.25, kCells), e = dense<GimpKernel>(face, 0.25, kCells);
    EXPECT_EQ(c.N, e.N);
  }
}

}  // namespace
}  // namespace mpm

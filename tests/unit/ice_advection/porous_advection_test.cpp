// Advection of densities through a porous medium (Advector::advance with a
// porosity): each density is reconstructed per unit of pore space.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "ice/advection/advection_time_step.hpp"
#include "ice/advection/advector.hpp"
#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"

namespace {

using ice::Limiter;

constexpr Limiter all_limiters[] = {Limiter::first_order, Limiter::minmod, Limiter::van_leer};

// Random velocities on interior faces, zero on the box's walls.
ice::FaceField<2> random_closed_box_velocity(const ice::CellGrid<2>& grid, std::mt19937& rng) {
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  ice::FaceField<2> u = ice::make_face_field(grid);
  for (int d = 0; d < 2; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const bool wall = grid.lower_cell(d, f) == -1 || grid.upper_cell(d, f) == -1;
      u[d][f] = wall ? 0.0 : speed(rng);
    }
  }
  return u;
}

double total(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum;
}

// A ramp of porosity (a staircase of half-filled cells beside a bed, seen
// along the flow): 0.05, 0.75, 1, 1, ... with the pores filled by a fluid of
// density 1000, flowing at Courant 0.2 from the ramp into the open cells.
// The first open cell after the ramp changes, per step, by what the pressure
// equation balances: the Courant number times (the donor's bulk density 750
// in, 1000 out); a limited reconstruction of the bulk density itself brings
// more in (up the ramp 50, 750, 1000), mass the pressure equation never saw.
TEST(PorousAdvection, AFilledPoreSpaceCarriesTheUpwindVolumeAcrossAJumpInPorosity) {
  const int cells = 8;
  const ice::CellGrid<1> grid(Eigen::Matrix<double, 1, 1>(0.0), Eigen::Matrix<double, 1, 1>(0.05),
                              {cells});
  std::vector<double> porosity(cells, 1.0);
  porosity[1] = 0.05;
  porosity[2] = 0.75;
  const double density = 1000.0;
  const double courant = 0.2;
  const double dt = 1e-3;
  const ice::FaceField<1> u = ice::make_face_field(grid, courant * 0.05 / dt);
  const double expected_change = courant * density * (porosity[2] - porosity[3]);  // in - out
  for (const Limiter limiter : all_limiters) {
    std::vector<double> plain(cells), porous(cells);
    for (int c = 0; c < cells; ++c) plain[c] = porous[c] = density * porosity[c];
    ice::Advector<1> advector(grid, limiter);
    advector.advance(u, dt, {plain});
    advector.advance(u, dt, std::vector<std::span<double>>{porous}, porosity);
    const double porous_change = porous[3] - density;
    const double plain_change = plain[3] - density;
    std::printf(
        "  %-11s: the first open cell changes by %.4f kg/m3 in a step (the pressure equation's "
        "upwind volumes: %.4f, tolerance 1e-12 relative); reconstructing rhobar itself %.4f\n",
        std::string(ice::to_string(limiter)).c_str(), porous_change, expected_change, plain_change);
    EXPECT_NEAR(porous_change, expected_change, 1e-12 * density);
    if (limiter != Limiter::first_order) {
      EXPECT_GT(plain_change, expected_change + 1.0);
    }
  }
}

// With every porosity 1 the porous path is the plain scheme, bit for bit.
TEST(PorousAdvection, AnOpenDomainAdvectsBitForBitAsWithoutAPorosity) {
  const ice::CellGrid<2> grid(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.1, 0.13), {9, 7});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(0.5, 1.5);
  const ice::FaceField<2> u = random_closed_box_velocity(grid, rng);
  const double dt = ice::advection_time_step(grid, u, 0.5);
  std::vector<double> a(static_cast<std::size_t>(grid.cell_count()));
  for (double& v : a) v = value(rng);
  std::vector<double> b = a;
  const std::vector<double> open(a.size(), 1.0);
  for (const Limiter limiter : all_limiters) {
    ice::Advector<2> advector(grid, limiter);
    for (int step = 0; step < 5; ++step) {
      advector.advance(u, dt, {a});
      advector.advance(u, dt, std::vector<std::span<double>>{b}, open);
    }
    EXPECT_EQ(a, b) << ice::to_string(limiter);
  }
}

// In a closed box with a random porosity the total is kept to round-off.
TEST(PorousAdvection, ConservesTheTotalInAClosedBoxWithARandomPorosity) {
  const ice::CellGrid<2> grid(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.1, 0.1), {12, 10});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pores(0.05, 1.0), fill(0.5, 1.5);
  const auto cells = static_cast<std::size_t>(grid.cell_count());
  std::vector<double> porosity(cells);
  for (double& n : porosity) n = pores(rng);
  for (const Limiter limiter : all_limiters) {
    std::vector<double> q(cells);
    for (std::size_t c = 0; c < cells; ++c) q[c] = fill(rng) * porosity[c];
    const double start = total(q);
    ice::Advector<2> advector(grid, limiter);
    double worst = 0.0;
    for (int step = 0; step < 20; ++step) {
      const ice::FaceField<2> u = random_closed_box_velocity(grid, rng);
      const double dt = ice::advection_time_step(grid, u, 0.25);
      advector.advance(u, dt, std::vector<std::span<double>>{q}, porosity);
      worst = std::max(worst, std::abs(total(q) - start) / start);
    }
    std::printf("  %-11s: 20 steps, worst relative change of the total %.2e (tolerance 1e-14)\n",
                std::string(ice::to_string(limiter)).c_str(), worst);
    EXPECT_LE(worst, 1e-14);
  }
}

TEST(PorousAdvection, RefusesAPorosityOfTheWrongSizeOrOutsideZeroToOne) {
  const ice::CellGrid<1> grid(Eigen::Matrix<double, 1, 1>(0.0), Eigen::Matrix<double, 1, 1>(0.1),
                              {4});
  ice::Advector<1> advector(grid, Limiter::van_leer);
  const ice::FaceField<1> u = ice::make_face_field(grid, 0.0);
  std::vector<double> q(4, 1.0);
  const std::vector<std::span<double>> fields{q};
  EXPECT_THROW(advector.advance(u, 0.01, fields, std::vector<double>(3, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(advector.advance(u, 0.01, fields, std::vector<double>{1.0, 0.0, 1.0, 1.0}),
               std::invalid_argument);
  EXPECT_THROW(advector.advance(u, 0.01, fields, std::vector<double>{1.0, 1.5, 1.0, 1.0}),
               std::invalid_argument);
  EXPECT_THROW(advector.advance(u, 0.01, fields, std::vector<double>{1.0, NAN, 1.0, 1.0}),
               std::invalid_argument);
}

}  // namespace

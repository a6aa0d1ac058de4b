#include "ice/advection/advector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "cosim/error.hpp"
#include "ice/advection/advection_time_step.hpp"
#include "ice/grid/cell_grid.hpp"
#include "ice/grid/grid_fields.hpp"

namespace {

using ice::Limiter;

constexpr Limiter all_limiters[] = {Limiter::first_order, Limiter::minmod, Limiter::van_leer};

// Neumaier's compensated sum, so the test's own round-off stays below the
// scheme's.
double exact_sum(const std::vector<double>& values) {
  double sum = 0.0;
  double compensation = 0.0;
  for (const double v : values) {
    const double t = sum + v;
    compensation += std::abs(sum) >= std::abs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
  }
  return sum + compensation;
}

template <int Dim>
ice::CellGrid<Dim> box_grid(const std::array<int, Dim>& cells) {
  using Point = typename ice::CellGrid<Dim>::Point;
  Point spacing;
  for (int d = 0; d < Dim; ++d) {
    spacing[d] = 0.1 + 0.03 * d;
  }
  return ice::CellGrid<Dim>(Point::Zero(), spacing, cells);
}

// Random velocities on interior faces, zero on the box's walls.
template <int Dim>
ice::FaceField<Dim> random_closed_box_velocity(const ice::CellGrid<Dim>& grid, std::mt19937& rng) {
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  ice::FaceField<Dim> u = ice::make_face_field(grid);
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const bool wall = grid.lower_cell(d, f) == -1 || grid.upper_cell(d, f) == -1;
      u[d][f] = wall ? 0.0 : speed(rng);
    }
  }
  return u;
}

// A discretely divergence-free velocity from a random stream function psi at
// the cell corners: U_x = d psi / dy, U_y = -d psi / dx on the faces, so the
// corner values cancel in every cell's net outflow. In 3D psi varies between
// layers and U_z depends on (x, y) only. psi is not zero on the boundary, so
// fluid enters and leaves through the domain's faces.
template <int Dim>
ice::FaceField<Dim> random_divergence_free_velocity(const ice::CellGrid<Dim>& grid,
                                                    std::mt19937& rng) {
  static_assert(Dim >= 2);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const auto& n = grid.cells();
  const int layers = Dim == 3 ? n[Dim - 1] : 1;
  const int corners = (n[0] + 1) * (n[1] + 1);
  std::vector<double> psi(static_cast<std::size_t>(corners * layers));
  for (double& p : psi) {
    p = 0.1 * value(rng);
  }
  std::vector<double> w(static_cast<std::size_t>(n[0] * n[1]));
  for (double& v : w) {
    v = value(rng);
  }
  auto corner = [&](int i, int j, int k) {
    return psi[static_cast<std::size_t>(i + (n[0] + 1) * (j + (n[1] + 1) * k))];
  };
  const double dx = grid.spacing()[0];
  const double dy = grid.spacing()[1];
  ice::FaceField<Dim> u = ice::make_face_field(grid);
  for (int d = 0; d < Dim; ++d) {
    for (int f = 0; f < grid.face_count(d); ++f) {
      const auto ijk = grid.face_ijk(d, f);
      const int i = ijk[0];
      const int j = ijk[1];
      const int k = Dim == 3 ? ijk[Dim - 1] : 0;
      if (d == 0) {
        u[d][f] = (corner(i, j + 1, k) - corner(i, j, k)) / dy;
      } else if (d == 1) {
        u[d][f] = -(corner(i + 1, j, k) - corner(i, j, k)) / dx;
      } else {
        u[d][f] = w[static_cast<std::size_t>(i + n[0] * j)];
      }
    }
  }
  return u;
}

template <int Dim>
void check_conservation_in_a_closed_box(const std::array<int, Dim>& cells, Limiter limiter) {
  const ice::CellGrid<Dim> grid = box_grid<Dim>(cells);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> density(0.5, 1.5);
  ice::CellField q = ice::make_cell_field(grid);
  for (double& v : q) {
    v = density(rng);
  }
  ice::Advector<Dim> advector(grid, limiter);
  const double start = exact_sum(q) * grid.cell_volume();
  double worst = 0.0;
  for (int step = 0; step < 20; ++step) {
    const ice::FaceField<Dim> u = random_closed_box_velocity(grid, rng);
    const double dt = ice::advection_time_step(grid, u, 0.5);
    advector.advance(u, dt, {q});
    worst = std::max(worst, std::abs(exact_sum(q) * grid.cell_volume() - start) / start);
  }
  const auto [lowest, highest] = std::minmax_element(q.begin(), q.end());
  std::printf(
      "  %dD %-11s: %d cells, 20 steps, worst relative change of the total %.2e "
      "(tolerance 1e-14); q in [%.3f, %.3f]\n",
      Dim, std::string(ice::to_string(limiter)).c_str(), grid.cell_count(), worst, *lowest,
      *highest);
  EXPECT_LE(worst, 1e-14);
  EXPECT_GT(*lowest, 0.0);
}

TEST(Advector, ConservesTheTotalInAClosedBox2D) {
  for (const Limiter limiter : all_limiters) {
    check_conservation_in_a_closed_box<2>({40, 30}, limiter);
  }
}

TEST(Advector, ConservesTheTotalInAClosedBox3D) {
  for (const Limiter limiter : all_limiters) {
    check_conservation_in_a_closed_box<3>({16, 12, 10}, limiter);
  }
}

template <int Dim>
void check_uniform_field_stays_uniform(const std::array<int, Dim>& cells, Limiter limiter) {
  const ice::CellGrid<Dim> grid = box_grid<Dim>(cells);
  std::mt19937 rng(777);
  const ice::FaceField<Dim> u = random_divergence_free_velocity(grid, rng);
  const double dt = ice::advection_time_step(grid, u, 0.5);
  const double value = 1.7;
  ice::CellField q = ice::make_cell_field(grid, value);
  ice::Advector<Dim> advector(grid, limiter);
  for (int step = 0; step < 20; ++step) {
    advector.advance(u, dt, {q});
  }
  double worst = 0.0;
  for (const double v : q) {
    worst = std::max(worst, std::abs(v - value) / value);
  }
  std::printf(
      "  %dD %-11s: 20 steps at Courant 0.5 through open boundaries, "
      "max |q - q0| / q0 = %.2e (tolerance 1e-14)\n",
      Dim, std::string(ice::to_string(limiter)).c_str(), worst);
  EXPECT_LE(worst, 1e-14);
}

TEST(Advector, KeepsAUniformFieldUniformUnderADivergenceFreeVelocity) {
  for (const Limiter limiter : all_limiters) {
    check_uniform_field_stays_uniform<2>({30, 20}, limiter);
    check_uniform_field_stays_uniform<3>({12, 10, 8}, limiter);
  }
}

TEST(Advector, AdvancesSeveralFieldsInOneCallAsOneAtATime) {
  const ice::CellGrid<2> grid = box_grid<2>({17, 13});
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> value(-1.0, 2.0);
  std::vector<ice::CellField> fields(3, ice::make_cell_field(grid));
  for (auto& field : fields) {
    for (double& v : field) {
      v = value(rng);
    }
  }
  const ice::FaceField<2> u = random_divergence_free_velocity(grid, rng);
  const double dt = ice::advection_time_step(grid, u, 0.4);
  const std::vector<ice::CellField> initial = fields;
  std::vector<ice::CellField> separate = fields;
  ice::Advector<2> together(grid, Limiter::van_leer);
  together.advance(u, dt, {fields[0], fields[1], fields[2]});
  for (auto& field : separate) {
    ice::Advector<2> alone(grid, Limiter::van_leer);
    alone.advance(u, dt, {field});
  }
  for (std::size_t k = 0; k < fields.size(); ++k) {
    EXPECT_EQ(fields[k], separate[k]) << "field " << k;
    EXPECT_NE(fields[k], initial[k]) << "field " << k;
  }
}

// Cell averages of a Gaussian bump on a background of 1, by 3-point
// Gauss-Legendre quadrature (error O(dx^6)).
std::vector<double> bump_cell_averages(const ice::CellGrid<1>& grid, double shift) {
  const double dx = grid.spacing()[0];
  const double node = std::sqrt(0.6) * 0.5 * dx;
  auto bump = [shift](double x) {
    const double r = (x - 0.25 - shift) / 0.05;
    return 1.0 + std::exp(-r * r);
  };
  std::vector<double> average(static_cast<std::size_t>(grid.cell_count()));
  for (int c = 0; c < grid.cell_count(); ++c) {
    const double x = grid.cell_centre(c)[0];
    average[static_cast<std::size_t>(c)] =
        (5.0 * bump(x - node) + 8.0 * bump(x) + 5.0 * bump(x + node)) / 18.0;
  }
  return average;
}

// L1 error after translating the bump by 0.5 at speed 1 and Courant 0.5;
// the background value 1 enters through the inflow face.
double translation_error(int cells, Limiter limiter) {
  const ice::CellGrid<1> grid(Eigen::Matrix<double, 1, 1>(0.0),
                              Eigen::Matrix<double, 1, 1>(1.0 / cells), {cells});
  ice::CellField q = bump_cell_averages(grid, 0.0);
  const ice::FaceField<1> u = ice::make_face_field(grid, 1.0);
  const int steps = cells;
  const double dt = 0.5 / steps;
  ice::Advector<1> advector(grid, limiter);
  for (int step = 0; step < steps; ++step) {
    advector.advance(u, dt, {q});
  }
  const std::vector<double> exact = bump_cell_averages(grid, 0.5);
  double error = 0.0;
  for (std::size_t c = 0; c < q.size(); ++c) {
    error += std::abs(q[c] - exact[c]) * grid.spacing()[0];
  }
  return error;
}

// Orders between successive refinements of the translated bump.
std::vector<double> observed_orders(Limiter limiter, const std::vector<int>& resolutions) {
  std::vector<double> errors;
  std::vector<double> orders;
  for (const int cells : resolutions) {
    errors.push_back(translation_error(cells, limiter));
    if (errors.size() > 1) {
      orders.push_back(std::log2(errors[errors.size() - 2] / errors.back()));
    }
    std::printf("  %-11s %5d cells: L1 error %.3e%s", std::string(ice::to_string(limiter)).c_str(),
                cells, errors.back(), orders.empty() ? "\n" : "");
    if (!orders.empty()) {
      std::printf(", observed order %.3f\n", orders.back());
    }
  }
  return orders;
}

TEST(Advector, VanLeerTranslatesASmoothBumpToSecondOrder) {
  const std::vector<double> orders = observed_orders(Limiter::van_leer, {100, 200, 400, 800, 1600});
  EXPECT_GT(orders.back(), 1.5) << "van_leer's order on the finest pair (asserted > 1.5)";
  EXPECT_GT(orders[orders.size() - 2], 1.5);
}

TEST(Advector, MinmodTranslatesASmoothBumpToMoreThanFirstOrder) {
  const std::vector<double> orders = observed_orders(Limiter::minmod, {100, 200, 400, 800, 1600});
  EXPECT_GT(orders.back(), 1.3) << "minmod's order on the finest pair (asserted > 1.3)";
}

TEST(Advector, FirstOrderTranslatesASmoothBumpToFirstOrder) {
  const std::vector<double> orders =
      observed_orders(Limiter::first_order, {200, 400, 800, 1600, 3200});
  EXPECT_NEAR(orders.back(), 1.0, 0.15) << "first_order's order on the finest pair (1 +- 0.15)";
}

TEST(Advector, LimitedSchemesCreateNoNewExtremaAtAStep1D) {
  const int cells = 200;
  const ice::CellGrid<1> grid(Eigen::Matrix<double, 1, 1>(0.0),
                              Eigen::Matrix<double, 1, 1>(1.0 / cells), {cells});
  const ice::FaceField<1> u = ice::make_face_field(grid, 1.0);
  const double dt = 0.9 / cells;  // Courant 0.9
  for (const Limiter limiter : all_limiters) {
    ice::CellField q = ice::make_cell_field(grid, 0.5);
    for (int c = 40; c < 100; ++c) {
      q[static_cast<std::size_t>(c)] = 2.0;
    }
    ice::Advector<1> advector(grid, limiter);
    double highest = 0.0;
    double lowest = 1.0;
    for (int step = 0; step < 100; ++step) {
      advector.advance(u, dt, {q});
      highest = std::max(highest, *std::max_element(q.begin(), q.end()));
      lowest = std::min(lowest, *std::min_element(q.begin(), q.end()));
    }
    // The step moved by U t = 0.45: its excess mass is now centred at 0.35 + 0.45.
    double excess = 0.0;
    double moment = 0.0;
    for (int c = 0; c < cells; ++c) {
      excess += q[static_cast<std::size_t>(c)] - 0.5;
      moment += (q[static_cast<std::size_t>(c)] - 0.5) * grid.cell_centre(c)[0];
    }
    std::printf(
        "  1D %-11s: 100 steps at Courant 0.9, q in [0.5 %+.1e, 2 %+.1e] "
        "(initial [0.5, 2]), step centre %.4f (exact 0.8, tolerance dx/2)\n",
        std::string(ice::to_string(limiter)).c_str(), lowest - 0.5, highest - 2.0, moment / excess);
    EXPECT_LE(highest, 2.0 * (1.0 + 1e-15));
    EXPECT_GE(lowest, 0.5 * (1.0 - 1e-15));
    EXPECT_NEAR(moment / excess, 0.8, 0.5 / cells);
  }
}

TEST(Advector, LimitedSchemesCreateNoNewExtremaAtAStep2D) {
  const ice::CellGrid<2> grid(Eigen::Vector2d::Zero(), Eigen::Vector2d(0.02, 0.02), {60, 60});
  ice::FaceField<2> u = ice::make_face_field(grid);
  std::fill(u[0].begin(), u[0].end(), 1.0);
  std::fill(u[1].begin(), u[1].end(), 0.6);
  const double dt = ice::advection_time_step(grid, u, 0.5);
  for (const Limiter limiter : all_limiters) {
    ice::CellField q = ice::make_cell_field(grid, 0.5);
    for (int c = 0; c < grid.cell_count(); ++c) {
      const auto x = grid.cell_centre(c);
      if (x[0] > 0.2 && x[0] < 0.5 && x[1] > 0.2 && x[1] < 0.5) {
        q[static_cast<std::size_t>(c)] = 2.0;
      }
    }
    ice::Advector<2> advector(grid, limiter);
    double highest = 0.0;
    double lowest = 1.0;
    for (int step = 0; step < 40; ++step) {
      advector.advance(u, dt, {q});
      highest = std::max(highest, *std::max_element(q.begin(), q.end()));
      lowest = std::min(lowest, *std::min_element(q.begin(), q.end()));
    }
    std::printf("  2D %-11s: 40 steps at Courant sum 0.5, q in [0.5 %+.1e, 2 %+.1e]\n",
                std::string(ice::to_string(limiter)).c_str(), lowest - 0.5, highest - 2.0);
    EXPECT_LE(highest, 2.0 * (1.0 + 1e-15));
    EXPECT_GE(lowest, 0.5 * (1.0 - 1e-15));
    EXPECT_LT(q[static_cast<std::size_t>(grid.cell({10, 10}))], 2.0);  // it moved off its start
  }
}

TEST(Advector, RefusesFieldsOfTheWrongSizeAndTooLongSteps) {
  const ice::CellGrid<2> grid = box_grid<2>({4, 3});
  ice::Advector<2> advector(grid, Limiter::minmod);
  ice::FaceField<2> u = ice::make_face_field(grid, 1.0);
  ice::CellField q = ice::make_cell_field(grid, 1.0);
  ice::CellField short_field(5, 1.0);
  EXPECT_THROW(advector.advance(u, 0.01, {q, short_field}), std::invalid_argument);
  EXPECT_THROW(advector.advance(u, -0.01, {q}), std::invalid_argument);
  ice::FaceField<2> wrong = u;
  wrong[1].pop_back();
  EXPECT_THROW(advector.advance(wrong, 0.01, {q}), std::invalid_argument);
  u[1][7] = 30.0;  // |U| dt / dy = 30 * 0.01 / 0.13 > 1
  EXPECT_THROW(advector.advance(u, 0.01, {q}), cosim::NumericalError);
  u[1][7] = std::nan("");
  EXPECT_THROW(advector.advance(u, 0.01, {q}), cosim::NumericalError);
}

}  // namespace

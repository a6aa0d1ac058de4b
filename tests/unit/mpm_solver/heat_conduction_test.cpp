// Heat conduction in the MPM solver (Tran et al., MPMICE, eqs. 55-56, 92):
// transient and steady conduction in a bar against the analytic solutions,
// exact conservation of the thermal energy, the porous skeleton's share of
// the conductivity and the explicit time step limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mpm/solver/solver.hpp"
#include "mpm_case_builder.hpp"

namespace mpm {
namespace {

using testing::box_body;
using testing::empty_case;

constexpr double pi = std::numbers::pi;

// An elastic material that stores and conducts heat; soft, so that the
// mechanical time step never limits these runs (nothing moves without loads).
std::shared_ptr<const Material> thermal_material(double density, double specific_heat,
                                                 double conductivity) {
  return testing::material_from_yaml(
      "type: linear_elastic\ndensity: " + std::to_string(density) +
      "\nyoungs_modulus: 1.0e-6\npoisson_ratio: 0.0\nspecific_heat: " +
      std::to_string(specific_heat) + "\nthermal_conductivity: " + std::to_string(conductivity) +
      "\n");
}

FaceTemperature fixed(double temperature) {
  return {FaceTemperature::Kind::fixed, temperature};
}

// A bar [0, 1] x [0, 2h] filling a grid of `cells` x 2 cells, rho = c = k = 1
// (diffusivity 1 m^2/s), initially at T0, x faces held at T_left and T_right.
struct Bar {
  double T0 = 300.0, T_left = 400.0, T_right = 350.0;
};

CaseDescription bar_case(int cells, ShapeKind shape, const Bar& bar) {
  const double h = 1.0 / cells;
  CaseDescription c = empty_case(2, {cells, 2, 1}, h);
  c.shape = shape;
  c.materials.push_back(thermal_material(1.0, 1.0, 1.0));
  c.bodies.push_back(box_body("bar", 0, 2, Vec3d::Zero(), Vec3d(1.0, 2.0 * h, 0.0), h, 2));
  c.bodies[0].initial_temperature = bar.T0;
  c.thermal.enabled = true;
  c.thermal.faces[0] = fixed(bar.T_left);
  c.thermal.faces[1] = fixed(bar.T_right);
  return c;
}

// T(x, t) of the bar: the steady line plus the decaying sine series of the
// initial difference from it (kappa = 1, L = 1).
double bar_temperature(const Bar& bar, double x, double t) {
  double T = bar.T_left + (bar.T_right - bar.T_left) * x;
  for (int n = 1; n <= 400; ++n) {
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    const double b =
        2.0 / (n * pi) * ((bar.T0 - bar.T_left) * (1.0 - sign) + (bar.T_right - bar.T_left) * sign);
    T += b * std::sin(n * pi * x) * std::exp(-n * n * pi * pi * t);
  }
  return T;
}

void run_to(Solver<2>& solver, double end) {
  while (solver.time() < end - 1e-12)
    solver.step(std::min(solver.stable_time_step(), end - solver.time()));
}

// Largest |T_p - T(x_p, t)| over the points, as a fraction of the largest
// temperature difference (100 K).
double bar_error(const Solver<2>& solver, const Bar& bar) {
  double error = 0.0;
  const auto& p = solver.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    error = std::max(
        error, std::abs(p.temperature[i] - bar_temperature(bar, p.position[i][0], solver.time())));
  return error / 100.0;
}

// Every shape converges at second order in the points' temperatures.
TEST(MpmHeatConduction, TransientBarFollowsTheFourierSeries) {
  const Bar bar;
  for (ShapeKind shape : {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline}) {
    const double tolerance = 1e-2;
    const double min_ratio = 3.5;  // error ratio per halving of h
    double previous = 0.0;
    for (int cells : {10, 20, 40}) {
      Solver<2> solver(bar_case(cells, shape, bar));
      run_to(solver, 0.05);
      const double error = bar_error(solver, bar);
      const double ratio = previous > 0.0 ? previous / error : 0.0;
      std::printf(
          "  %-17s %2d cells, t = 0.05 s (%4zu steps): max |T - T_exact| = %.3e of dT, ratio %.2f "
          "(tolerances %.0e at 40 cells, ratio >= %.1f)\n",
          std::string(to_string(shape)).c_str(), cells, solver.step_count(), error, ratio,
          tolerance, min_ratio);
      if (cells == 40) {
        EXPECT_LT(error, tolerance) << to_string(shape);
      }
      if (previous > 0.0) {
        EXPECT_GT(ratio, min_ratio) << to_string(shape) << " " << cells;
      }
      previous = error;
    }
  }
}

TEST(MpmHeatConduction, BarReachesTheSteadyLinearProfile) {
  const Bar bar;
  for (ShapeKind shape : {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline}) {
    Solver<2> solver(bar_case(10, shape, bar));
    const double initial = solver.totals().thermal_energy;
    run_to(solver, 1.5);  // the slowest mode has decayed to exp(-1.5 pi^2) = 4e-7
    const auto& p = solver.particles();
    const auto& grid = solver.grid();
    // The grid values reproduce the line, and so do the points.
    double grid_error = 0.0, interior_error = 0.0, wall_error = 0.0;
    for (std::size_t i = 0; i < grid.size(); ++i)
      if (grid.heat_capacity[i] > 0.0) {
        const double x = grid.position(i)[0];
        grid_error =
            std::max(grid_error, std::abs(grid.temperature[i] - bar_temperature(bar, x, 1e9)));
      }
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double x = p.position[i][0];
      const double error = std::abs(p.temperature[i] - bar_temperature(bar, x, 1e9)) / 50.0;
      double& worst = x > 0.1 && x < 0.9 ? interior_error : wall_error;
      worst = std::max(worst, error);
    }
    grid_error /= 50.0;
    const double interior_tolerance = 1e-5, wall_tolerance = 1e-5;
    std::printf(
        "  %-17s steady: grid values %.2e, points off the face cells %.2e, points in them %.2e of "
        "dT "
        "(tolerances 1e-5, %.0e, %.0e)\n",
        std::string(to_string(shape)).c_str(), grid_error, interior_error, wall_error,
        interior_tolerance, wall_tolerance);
    EXPECT_LT(grid_error, 1e-5);
    EXPECT_LT(interior_error, interior_tolerance);
    EXPECT_LT(wall_error, wall_tolerance);
    const Totals<2> t = solver.totals();
    // What entered through the faces is what the bar gained.
    const double balance = std::abs(t.thermal_energy - initial - t.heat_through_faces) / initial;
    std::printf(
        "  %-17s thermal energy %.9g J/m, in through faces %.9g J/m: balance %.2e (tolerance "
        "1e-12)\n",
        std::string(to_string(shape)).c_str(), t.thermal_energy, t.heat_through_faces, balance);
    EXPECT_LT(balance, 1e-12);
  }
}

// A block of points with random temperatures moving across cells beside a
// rigid plate that conducts, in a closed box: sum m c T is conserved.
template <int Dim>
void expect_insulated_box_conserves(ShapeKind shape) {
  CaseDescription c = empty_case(Dim, {8, 8, 8}, 0.125);
  c.shape = shape;
  c.materials.push_back(
      testing::material_from_yaml("type: linear_elastic\ndensity: 2000\nyoungs_modulus: "
                                  "1.0e5\npoisson_ratio: 0.3\nspecific_heat: 1\n"
                                  "thermal_conductivity: 1000\n"));
  c.bodies.push_back(
      box_body("block", 0, Dim, Vec3d::Constant(0.25), Vec3d::Constant(0.75), 0.125, 2));
  c.bodies[0].initial_velocity = Vec3d(0.2, 0.1, 0.1);
  BodySpec plate = box_body("plate", -1, Dim, Vec3d::Constant(0.0),
                            Vec3d(1.0, 0.25, Dim == 3 ? 1.0 : 0.0), 0.125, 2);
  plate.rigid = RigidMotion{};
  plate.density_override = 7800.0;
  plate.thermal_override = ThermalProperties{.specific_heat = 1.0, .conductivity = 4000.0};
  plate.initial_temperature = 350.0;
  c.bodies.push_back(plate);
  c.thermal.enabled = true;
  Solver<Dim> solver(c);
  auto& particles = solver.particles();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(250.0, 400.0);
  for (std::size_t p = 0; p < particles.size(); ++p)
    if (particles.body[p] == 0) particles.temperature[p] = u(rng);
  // The rigid plate (350 K) and the block (325 K on average) exchange heat
  // (diffusivities 0.5 m^2/s: the conduction limit is the time step).
  const auto plate_temperature = [&] {
    double CT = 0.0, C = 0.0;
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (particles.body[p] == 1) {
        CT += particles.heat_capacity[p] * particles.temperature[p];
        C += particles.heat_capacity[p];
      }
    return CT / C;
  };
  const double before = solver.totals().thermal_energy;
  const double plate_before = plate_temperature();
  const double dt = 0.5 * solver.stable_time_step();
  const int steps = Dim == 2 ? 200 : 60;
  for (int n = 0; n < steps; ++n) solver.step(dt);
  solver.check_state();
  const double plate_after = plate_temperature();
  const Totals<Dim> t = solver.totals();
  const double error = std::abs(t.thermal_energy - before) / before;
  std::printf(
      "  %dD %-17s %d steps: thermal energy %.15g -> %.15g J, relative change %.2e (tolerance "
      "1e-12)\n",
      Dim, std::string(to_string(shape)).c_str(), steps, before, t.thermal_energy, error);
  EXPECT_LT(error, 1e-12);
  EXPECT_EQ(t.heat_through_faces, 0.0);
  std::printf("  %dD %-17s rigid plate %.6f K -> %.6f K\n", Dim,
              std::string(to_string(shape)).c_str(), plate_before, plate_after);
  EXPECT_LT(plate_after, plate_before - 0.1);
}

TEST(MpmHeatConduction, InsulatedBoxConservesThermalEnergy2D) {
  for (ShapeKind shape : {ShapeKind::linear, ShapeKind::gimp, ShapeKind::quadratic_bspline})
    expect_insulated_box_conserves<2>(shape);
}

TEST(MpmHeatConduction, InsulatedBoxConservesThermalEnergy3D) {
  for (ShapeKind shape : {ShapeKind::gimp, ShapeKind::quadratic_bspline})
    expect_insulated_box_conserves<3>(shape);
}

TEST(MpmHeatConduction, HeatSourcesAddExactlyTheirHeat) {
  CaseDescription c = bar_case(10, ShapeKind::gimp, Bar{});
  c.thermal.faces = {};
  Solver<2> solver(c);
  solver.add_particle_heat_source([](double, double, Particles<2>& particles) {
    for (std::size_t p = 0; p < particles.size(); ++p)
      particles.external_heat[p] += 0.5 + 0.01 * static_cast<double>(p);
  });
  const double before = solver.totals().thermal_energy;
  for (int n = 0; n < 50; ++n) solver.step(0.3 * solver.stable_time_step());
  const Totals<2> t = solver.totals();
  double rate = 0.0;
  for (std::size_t p = 0; p < solver.particles().size(); ++p)
    rate += 0.5 + 0.01 * static_cast<double>(p);
  const double error = std::abs(t.thermal_energy - before - t.external_heat) / t.external_heat;
  std::printf(
      "  heat in %.12g J/m (rate x time %.12g), thermal energy gained %.12g J/m: relative error "
      "%.2e "
      "(tolerance 1e-10)\n",
      t.external_heat, rate * solver.time(), t.thermal_energy - before, error);
  EXPECT_NEAR(t.external_heat, rate * solver.time(), 1e-12 * t.external_heat);
  EXPECT_LT(error, 1e-10);
}

// A porous skeleton conducts with (1 - n) k_s: it behaves exactly as a solid
// of density (1 - n) rho_s and conductivity (1 - n) k_s, and in series with a
// solid of conductivity k_s the steady interface temperature is
// (k_L T_L + k_R T_R) / (k_L + k_R) with k_L = (1 - n) k_s.
TEST(MpmHeatConduction, PorousSkeletonConductsWithItsSolidShare) {
  const double n = 0.5;
  const Bar bar;
  CaseDescription porous = bar_case(20, ShapeKind::gimp, bar);
  porous.bodies[0].porous = PorousSpec{.porosity = n, .grain_size = 1e-3};
  CaseDescription equivalent = bar_case(20, ShapeKind::gimp, bar);
  equivalent.materials[0] = thermal_material(1.0 - n, 1.0, 1.0 - n);
  Solver<2> a(porous), b(equivalent);
  run_to(a, 0.02);
  run_to(b, 0.02);
  double difference = 0.0;
  for (std::size_t p = 0; p < a.particles().size(); ++p)
    difference =
        std::max(difference, std::abs(a.particles().temperature[p] - b.particles().temperature[p]));
  std::printf(
      "  porous (n = %.1f) vs solid with (1 - n) rho, (1 - n) k: max |dT| = %.2e K (tolerance "
      "1e-9)\n",
      n, difference);
  EXPECT_EQ(a.step_count(), b.step_count());
  EXPECT_LT(difference, 1e-9);

  // Left half porous, right half solid, in series.
  const double h = 0.1;
  CaseDescription series = empty_case(2, {10, 2, 1}, h);
  series.materials.push_back(thermal_material(1.0, 1.0, 1.0));
  series.bodies.push_back(
      box_body("skeleton", 0, 2, Vec3d::Zero(), Vec3d(0.5, 2.0 * h, 0.0), h, 2));
  series.bodies[0].porous = PorousSpec{.porosity = n, .grain_size = 1e-3};
  series.bodies.push_back(
      box_body("rock", 0, 2, Vec3d(0.5, 0.0, 0.0), Vec3d(1.0, 2.0 * h, 0.0), h, 2));
  for (auto& body : series.bodies) body.initial_temperature = bar.T0;
  series.thermal.enabled = true;
  series.thermal.faces[0] = fixed(bar.T_left);
  series.thermal.faces[1] = fixed(bar.T_right);
  Solver<2> s(series);
  run_to(s, 2.5);
  const double k_left = 1.0 - n, k_right = 1.0;
  const double interface = (k_left * bar.T_left + k_right * bar.T_right) / (k_left + k_right);
  double at_interface = 0.0;
  for (std::size_t i = 0; i < s.grid().size(); ++i)
    if (std::abs(s.grid().position(i)[0] - 0.5) < 1e-9 &&
        std::abs(s.grid().position(i)[1] - h) < 1e-9)
      at_interface = s.grid().temperature[i];
  const double error = std::abs(at_interface - interface) / 50.0;
  std::printf(
      "  series porous | solid: interface %.6f K vs (k_L T_L + k_R T_R) / (k_L + k_R) = %.6f K "
      "(k_s alone would give %.1f K): error %.2e of dT (tolerance 1e-2)\n",
      at_interface, interface, 0.5 * (bar.T_left + bar.T_right), error);
  EXPECT_LT(error, 1e-2);
}

TEST(MpmHeatConduction, TimeStepHonoursTheConductionLimit) {
  CaseDescription c = bar_case(20, ShapeKind::gimp, Bar{});
  c.materials[0] = thermal_material(2.0, 3.0, 0.5);
  c.time.safety_factor = 0.4;
  Solver<2> solver(c);
  const double kappa = 0.5 / (2.0 * 3.0);
  const double limit = 0.4 * 0.05 * 0.05 / (2.0 * 2.0 * kappa);
  EXPECT_NEAR(solver.stable_time_step(), limit, 1e-12 * limit);
  c.thermal.enabled = false;
  EXPECT_GT(Solver<2>(c).stable_time_step(), 10.0 * limit);  // the soft material's wave limit alone
}

TEST(MpmHeatConduction, DisabledHeatLeavesTemperaturesAlone) {
  CaseDescription c = bar_case(10, ShapeKind::gimp, Bar{});
  c.thermal.enabled = false;
  Solver<2> solver(c);
  for (int k = 0; k < 10; ++k) solver.step(1e-3);
  for (double T : solver.particles().temperature) ASSERT_EQ(T, 300.0);
  EXPECT_FALSE(solver.conducts_heat());
  EXPECT_EQ(solver.totals().thermal_energy, 0.0);
}

}  // namespace
}  // namespace mpm

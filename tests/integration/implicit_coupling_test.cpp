// `cosim run` with the parallel-implicit scheme on two test participants
// whose answers depend on what they read: a writes 1 + 0.5 b, b writes
// 2 - 3 a, per cell. The fixed point a = 0.8, b = -0.4 is each window's
// answer; explicit coupling's Jacobi iteration over windows diverges
// (|0.5 * 3| > 1), the implicit scheme converges inside every window.
// Outputs are written once per window, and the bad inputs of implicit
// coupling are refused with the key, or the window and the field.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "model_jobs.hpp"
#include "run_process.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr double a_exact = 0.8, b_exact = -0.4;

const std::string implicit_iqn = R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: right.a, relative: 1.0e-10}
    - {field: left.b, relative: 1.0e-10}
  acceleration: {method: iqn-ils}
)";

ProcessResult cosim_run(const fs::path& dir) {
  return run({binary("cosim").string(), "run", (dir / "job.yaml").string(), "--output",
              (dir / "run").string()},
             std::chrono::seconds(120));
}

// The mean of what a participant read at each window start (its read log).
std::vector<double> reads_per_window(const fs::path& file) {
  std::vector<double> means;
  for (const auto& row : read_csv(file)) means.push_back(row[2] / 4.0);
  return means;
}

TEST(ImplicitCoupling, ConvergesToTheFixedPointInEveryWindowAndWritesOnce) {
  const fs::path dir = fresh_directory("e2e_implicit");
  write_fixed_point_case(dir, implicit_iqn);
  const auto r = cosim_run(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const auto a_read = reads_per_window(dir / "run" / "right" / "a_read.csv");
  const auto b_read = reads_per_window(dir / "run" / "left" / "b_read.csv");
  ASSERT_EQ(a_read.size(), 10u);  // one row per window: none for a repeated one
  ASSERT_EQ(b_read.size(), 10u);
  double worst = 0.0;
  for (std::size_t w = 1; w < a_read.size(); ++w)
    worst = std::max({worst, std::abs(a_read[w] - a_exact) / a_exact,
                      std::abs(b_read[w] - b_exact) / std::abs(b_exact)});
  const auto iterations = read_csv(dir / "run" / "coupling_iterations.csv");
  ASSERT_EQ(iterations.size(), 10u);
  std::vector<double> counts;
  for (const auto& row : iterations) {
    EXPECT_EQ(row[3], 1.0) << "window " << row[0] << " did not converge";
    counts.push_back(row[2]);
  }
  std::sort(counts.begin(), counts.end());
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  std::printf(
      "implicit fixed point: worst relative error of the read values %.2e (tolerance 1e-8); "
      "iterations per window median %.1f, max %.0f\n",
      worst, counts[counts.size() / 2], counts.back());
  EXPECT_LE(worst, 1e-8);
  EXPECT_LE(counts[counts.size() / 2], 5.0);
  EXPECT_EQ(summary["coupling"]["windows"].get<int>(), 10);
  EXPECT_EQ(summary["coupling"]["windows_not_converged"].get<int>(), 0);
  for (const char* participant : {"left", "right"}) {
    const auto own = nlohmann::json::parse(read_text(dir / "run" / participant / "summary.json"));
    EXPECT_EQ(own["windows"].get<int>(), 10) << participant;
  }
  EXPECT_THAT(read_text(dir / "run" / "coupling_iterations.csv"),
              HasSubstr("right.a relative residual [1]"));
}

TEST(ImplicitCoupling, ExplicitCouplingOfTheSameProblemDiverges) {
  const fs::path dir = fresh_directory("e2e_implicit_explicit");
  write_fixed_point_case(dir, "");
  const auto r = cosim_run(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto a_read = reads_per_window(dir / "run" / "right" / "a_read.csv");
  const double last_error = std::abs(a_read.back() - a_exact);
  std::printf("explicit fixed point: |a - a*| grows from %.3g to %.3g over %zu windows\n",
              std::abs(a_read[1] - a_exact), last_error, a_read.size());
  // Every two windows the error grows by |0.5 * -3| = 1.5.
  EXPECT_GT(last_error, 4.0 * std::abs(a_read[1] - a_exact));
}

// The parallel scheme's Jacobian here, [[0, 0.5], [-3, 0]] per cell, has the
// eigenvalues +-i sqrt(1.5): one scalar factor (Aitken's) cannot aim at both,
// and Aitken stalls where constant relaxation (|1 - w + i w sqrt(1.5)| < 1
// for w < 0.8) and IQN-ILS converge. Aitken is reported, not asserted.
TEST(ImplicitCoupling, ConstantAndQuasiNewtonConvergeAndAitkenIsReported) {
  for (const char* method : {"constant", "aitken", "iqn-ils", "iqn-imvj"}) {
    const bool asserted = std::string(method) != "aitken";
    const fs::path dir = fresh_directory(std::string("e2e_implicit_") + method);
    write_fixed_point_case(dir, fmt::format(R"(coupling:
  scheme: parallel-implicit
  max_iterations: 200
  on_max_iterations: continue
  convergence: [{{field: right.a, relative: 1.0e-8}}, {{field: left.b, relative: 1.0e-8}}]
  acceleration: {{method: {}, relaxation: 0.3}}
)",
                                            method));
    const auto r = cosim_run(dir);
    ASSERT_EQ(r.exit_code, 0) << method << "\n" << r.output;
    const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
    const double median = summary["coupling"]["median_iterations_per_window"].get<double>();
    const int not_converged = summary["coupling"]["windows_not_converged"].get<int>();
    std::printf("%s: median %.1f iterations per window, %d of 10 windows not converged in 200\n",
                method, median, not_converged);
    if (asserted) {
      EXPECT_EQ(not_converged, 0) << method;
    }
  }
}

TEST(ImplicitCoupling, TimeInterpolationOfAConstantFixedPointChangesNothing) {
  const fs::path dir = fresh_directory("e2e_implicit_linear");
  write_fixed_point_case(dir, implicit_iqn + "  time_interpolation: linear\n");
  const auto r = cosim_run(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto a_read = reads_per_window(dir / "run" / "right" / "a_read.csv");
  EXPECT_NEAR(a_read.back(), a_exact, 1e-8);
}

TEST(ImplicitCoupling, AParticipantThatCannotRepeatIsRefusedAtTheScheme) {
  const fs::path dir = fresh_directory("e2e_implicit_not_repeatable");
  write_fixed_point_case(dir, implicit_iqn, 0.5, -3.0, "[--not-repeatable]");
  const auto r = cosim_run(dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("job.yaml:23:11: key 'coupling.scheme'"));
  EXPECT_THAT(r.output, HasSubstr("participant 'right' (cosim participant"));
}

TEST(ImplicitCoupling, MaxIterationsStopsWithTheWindowAndTheFieldOrContinues) {
  const std::string limited = R"(coupling:
  scheme: parallel-implicit
  max_iterations: 3
  on_max_iterations: ON_MAX
  convergence: [{field: right.a, relative: 1.0e-12}]
  acceleration: {method: constant, relaxation: 0.2}
)";
  {
    const fs::path dir = fresh_directory("e2e_implicit_stop");
    std::string c = limited;
    c.replace(c.find("ON_MAX"), 6, "stop");
    write_fixed_point_case(dir, c);
    const auto r = cosim_run(dir);
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_THAT(r.output, HasSubstr("window 1 (t = 0.01 s) has not converged in 3 iterations"));
    EXPECT_THAT(r.output, HasSubstr("'right.a' residual"));
    EXPECT_EQ(read_csv(dir / "run" / "right" / "a_read.csv").size(), 0u);
  }
  {
    const fs::path dir = fresh_directory("e2e_implicit_continue");
    std::string c = limited;
    c.replace(c.find("ON_MAX"), 6, "continue");
    write_fixed_point_case(dir, c);
    const auto r = cosim_run(dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
    EXPECT_EQ(summary["coupling"]["windows_not_converged"].get<int>(), 10);
    EXPECT_EQ(summary["coupling"]["max_iterations_per_window"].get<int>(), 3);
  }
}

TEST(ImplicitCoupling, ADivergingResidualStopsTheRun) {
  const fs::path dir = fresh_directory("e2e_implicit_diverging");
  write_fixed_point_case(dir, R"(coupling:
  scheme: parallel-implicit
  divergence_factor: 10
  convergence: [{field: right.a, relative: 1.0e-10}]
  acceleration: {method: none}
)",
                         40.0, -40.0);
  const auto r = cosim_run(dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_THAT(r.output, HasSubstr("window 1 (t = 0.01 s): the implicit coupling diverges: the "
                                  "residual of 'right.a' grew"));
}

// The model problem with a known answer: a fluid (rho_bar_f = 600 kg/m^3,
// pushed by f = 6000 N/m^3) drags a porous solid (rho_bar_s = 1590 kg/m^3)
// through a constant K whose relaxation time tau = 1 / (K (1/rho_f +
// 1/rho_s)) = 1e-6 s is 1e-4 of the window. Exactly, the relative velocity
// w = u_f - u_s = a tau (1 - exp(-t / tau)), a = f / rho_f, and the
// momentum rho_f u_f + rho_s u_s = f t. The implicit scheme's exchange on the
// window's predicted velocities gives w within 1 % at a window 1e4 tau; the
// explicit exchange, lagged a window, leaves w = a dt (shown, not asserted).
struct DragRun {
  double worst_relative_velocity_error = 0.0;  // |w - w_exact| / w_exact over windows
  double worst_momentum_error = 0.0;           // |p - f t| / (f t)
  double last_relative_velocity = 0.0;
};

DragRun drag_run(const fs::path& dir) {
  const auto fluid = read_csv(dir / "run" / "water" / "fluid_velocity_window_end.csv");
  const auto solid = read_csv(dir / "run" / "soil" / "solid_velocity_window_end.csv");
  EXPECT_EQ(fluid.size(), 10u);
  EXPECT_EQ(solid.size(), 10u);
  DragRun out;
  const double a = model_force / model_rho_f;
  for (std::size_t n = 0; n < std::min(fluid.size(), solid.size()); ++n) {
    const double t = fluid[n][1];
    const double w = fluid[n][2] - solid[n][2];
    const double w_exact = a * model_tau * (1.0 - std::exp(-t / model_tau));
    const double momentum = model_rho_f * fluid[n][2] + model_rho_s * solid[n][2];
    out.worst_relative_velocity_error =
        std::max(out.worst_relative_velocity_error, std::abs(w - w_exact) / w_exact);
    out.worst_momentum_error = std::max(out.worst_momentum_error,
                                        std::abs(momentum - model_force * t) / (model_force * t));
    out.last_relative_velocity = w;
  }
  return out;
}

TEST(ImplicitCoupling, StiffDragMatchesTheExactSolutionAtAWindowOf1e4RelaxationTimes) {
  const fs::path dir = fresh_directory("e2e_implicit_drag");
  write_stiff_drag_case(dir, R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: water.momentum_exchange_impulse, relative: 1.0e-8}
    - {field: soil.momentum_exchange_impulse, relative: 1.0e-8}
)");
  const auto r = cosim_run(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const DragRun implicit_run = drag_run(dir);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  const double median = summary["coupling"]["median_iterations_per_window"].get<double>();

  const fs::path explicit_dir = fresh_directory("e2e_explicit_drag");
  write_stiff_drag_case(explicit_dir, "");
  ASSERT_EQ(cosim_run(explicit_dir).exit_code, 0);
  const DragRun explicit_run = drag_run(explicit_dir);
  std::printf(
      "stiff drag, window = 1e4 tau: implicit w error %.2e (tolerance 1e-2), momentum error "
      "%.2e, median %.1f iterations per window; explicit w = %.4g m/s against %.4g m/s exact "
      "(error %.3g)\n",
      implicit_run.worst_relative_velocity_error, implicit_run.worst_momentum_error, median,
      explicit_run.last_relative_velocity, model_force / model_rho_f * model_tau,
      explicit_run.worst_relative_velocity_error);
  EXPECT_LE(implicit_run.worst_relative_velocity_error, 1e-2);
  EXPECT_LE(implicit_run.worst_momentum_error, 1e-10);
  EXPECT_LE(median, 5.0);
  EXPECT_GT(explicit_run.worst_relative_velocity_error, 1.0);
}

// The energy exchange's model problem: a heated fluid (C_f = 1.67e6 J/(m^3 K),
// S = 1e6 W/m^3) exchanges heat with a solid (C_s = 1.25e6 J/(m^3 K)) at a
// coefficient H whose relaxation time tau = 1 / (H (1/C_f + 1/C_s)) = 1e-6 s
// is 1e-4 of the window. Exactly, the temperature difference theta = T_f - T_s
// = (S / C_f) tau (1 - exp(-t / tau)), and C_f T_f + C_s T_s = C (300 K) + S t.
// The implicit scheme's exchange on the window's predicted temperatures,
// T* = T - Q / (C V), gives theta within 1 %; the explicit one, lagged a
// window, leaves theta = S dt / C_f (shown, not asserted).
struct HeatRun {
  double worst_difference_error = 0.0;  // |theta - theta_exact| / theta_exact over windows
  double worst_energy_error = 0.0;      // |E - E_exact| / (S t)
  double last_difference = 0.0;
};

HeatRun heat_run(const fs::path& dir) {
  const auto fluid = read_csv(dir / "run" / "water" / "fluid_temperature_window_end.csv");
  const auto solid = read_csv(dir / "run" / "rock" / "solid_temperature_window_end.csv");
  EXPECT_EQ(fluid.size(), 10u);
  EXPECT_EQ(solid.size(), 10u);
  HeatRun out;
  for (std::size_t n = 0; n < std::min(fluid.size(), solid.size()); ++n) {
    const double t = fluid[n][1];
    const double theta = fluid[n][2] - solid[n][2];
    const double theta_exact = heat_source / heat_c_f * heat_tau * (1.0 - std::exp(-t / heat_tau));
    const double energy = heat_c_f * (fluid[n][2] - heat_t0) + heat_c_s * (solid[n][2] - heat_t0);
    out.worst_difference_error =
        std::max(out.worst_difference_error, std::abs(theta - theta_exact) / theta_exact);
    out.worst_energy_error =
        std::max(out.worst_energy_error, std::abs(energy - heat_source * t) / (heat_source * t));
    out.last_difference = theta;
  }
  return out;
}

TEST(ImplicitCoupling, StiffHeatExchangeMatchesTheExactSolutionAtAWindowOf1e4RelaxationTimes) {
  const fs::path dir = fresh_directory("e2e_implicit_heat");
  write_stiff_heat_case(dir, R"(coupling:
  scheme: parallel-implicit
  convergence:
    - {field: water.heat_exchange_energy, relative: 1.0e-8}
    - {field: rock.heat_exchange_energy, relative: 1.0e-8}
)");
  const auto r = cosim_run(dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const HeatRun implicit_run = heat_run(dir);
  const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  const double median = summary["coupling"]["median_iterations_per_window"].get<double>();

  const fs::path explicit_dir = fresh_directory("e2e_explicit_heat");
  write_stiff_heat_case(explicit_dir, "");
  ASSERT_EQ(cosim_run(explicit_dir).exit_code, 0);
  const HeatRun explicit_run = heat_run(explicit_dir);
  std::printf(
      "stiff heat exchange, window = 1e4 tau: implicit theta error %.2e (tolerance 1e-2), energy "
      "error %.2e, median %.1f iterations per window; explicit theta = %.4g K against %.4g K "
      "exact (error %.3g)\n",
      implicit_run.worst_difference_error, implicit_run.worst_energy_error, median,
      explicit_run.last_difference, heat_source / heat_c_f * heat_tau,
      explicit_run.worst_difference_error);
  EXPECT_LE(implicit_run.worst_difference_error, 1e-2);
  EXPECT_LE(implicit_run.worst_energy_error, 1e-9);
  EXPECT_LE(median, 5.0);
  EXPECT_GT(explicit_run.worst_difference_error, 1.0);
}

// Waveform relaxation: y' = -z and z' = y, split between two participants
// that sub-cycle 20 steps a window (midpoint rule, the partner's field read
// at each step's middle), y = cos t and z = sin t exactly. Reading the
// iterate of the window-end value, held over the window, is first order in
// the window; reading it linear in time between the window's two ends is
// second order: halving the window divides the error at t = 1 s by about 2
// and by about 4.
double oscillator_error(const std::string& scheme, const std::string& interpolation,
                        double window) {
  const fs::path dir = fresh_directory("e2e_waveform_" + scheme + "_" + interpolation);
  const std::string grid = "mesh: {dim: 1, origin: [0.0], spacing: [0.25], cells: [4]}\n";
  write_text(dir / "job.yaml", fmt::format(R"(kind: job
name: oscillator
end_time: 1.0
window: {0}
participants:
  left:
    executable: cosim_test_participant
    config: left.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{y: grid}}
    reads: {{z: grid}}
  right:
    executable: cosim_test_participant
    config: right.yaml
    meshes: {{grid: {{kind: uniform_grid, dim: 1}}}}
    writes: {{z: grid}}
    reads: {{y: grid}}
exchange:
  - {{field: y, from: left, to: right, mapping: consistent}}
  - {{field: z, from: right, to: left, mapping: consistent}}
coupling:
  scheme: {2}
  time_interpolation: {1}
{3})",
                                           window, interpolation, scheme,
                                           scheme.ends_with("implicit")
                                               ? "  convergence: [{field: right.y, absolute: "
                                                 "1.0e-13}, {field: left.z, absolute: 1.0e-13}]\n"
                                               : ""));
  const std::string dt = fmt::format("dt: {}\n", window / 20.0);
  write_text(dir / "left.yaml", "kind: test_participant\n" + dt + grid +
                                    "writes: [{name: y}]\nreads: [{name: z}]\n"
                                    "ode: {state: y, rate_from: z, coefficient: -1.0, initial: "
                                    "1.0}\n");
  write_text(dir / "right.yaml", "kind: test_participant\n" + dt + grid +
                                     "writes: [{name: z}]\nreads: [{name: y}]\n"
                                     "ode: {state: z, rate_from: y, coefficient: 1.0, initial: "
                                     "0.0}\n");
  const auto r = cosim_run(dir);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const auto y = read_csv(dir / "run" / "left" / "y_window_end.csv");
  if (y.empty()) return NAN;
  EXPECT_NEAR(y.back()[1], 1.0, 1e-12);
  return std::abs(y.back()[2] - std::cos(1.0));
}

struct OrderInTheWindow {
  double constant_coarse, constant_fine, linear_coarse, linear_fine;
  double constant_order() const { return std::log2(constant_coarse / constant_fine); }
  double linear_order() const { return std::log2(linear_coarse / linear_fine); }
};

OrderInTheWindow oscillator_orders(const std::string& scheme) {
  OrderInTheWindow o{
      oscillator_error(scheme, "constant", 0.1), oscillator_error(scheme, "constant", 0.05),
      oscillator_error(scheme, "linear", 0.1), oscillator_error(scheme, "linear", 0.05)};
  std::printf(
      "%s, oscillator y(1 s): constant interpolation errors %.3e, %.3e (order %.2f); linear "
      "%.3e, %.3e (order %.2f)\n",
      scheme.c_str(), o.constant_coarse, o.constant_fine, o.constant_order(), o.linear_coarse,
      o.linear_fine, o.linear_order());
  return o;
}

TEST(ImplicitCoupling, LinearTimeInterpolationIsSecondOrderInTheWindow) {
  const OrderInTheWindow o = oscillator_orders("parallel-implicit");
  EXPECT_NEAR(o.constant_order(), 1.0, 0.2);
  EXPECT_NEAR(o.linear_order(), 2.0, 0.2);
  EXPECT_LT(o.linear_fine, 0.1 * o.constant_fine);
}

// Serially the second participant reads the first's new window-end values:
// linear in time from the window's start they are second order once the
// window is iterated (the first then reads the second's iterate alike).
// Explicitly the first still holds the second's window-start values, which
// keeps the scheme first order; interpolating the second's reads only
// shrinks its error.
TEST(ImplicitCoupling, SerialSchemesReadTheFirstsNewValuesLinearInTime) {
  const OrderInTheWindow implicit_run = oscillator_orders("serial-implicit");
  EXPECT_NEAR(implicit_run.constant_order(), 1.0, 0.2);
  EXPECT_NEAR(implicit_run.linear_order(), 2.0, 0.2);
  EXPECT_LT(implicit_run.linear_fine, 0.1 * implicit_run.constant_fine);
  const OrderInTheWindow explicit_run = oscillator_orders("serial-explicit");
  EXPECT_NEAR(explicit_run.constant_order(), 1.0, 0.2);
  EXPECT_NEAR(explicit_run.linear_order(), 1.0, 0.2);
  EXPECT_LT(explicit_run.linear_fine, explicit_run.constant_fine);
}

// Serial schemes on the same fixed point: left runs each window first on
// b of the window before, right then on left's new a. Explicitly that is a
// Gauss-Seidel step, a_n = 2 - 1.5 a_{n-1}, which diverges; implicitly it
// converges, and, the gain being real, Aitken's one factor finds it in a few
// iterations as IQN-ILS does.
TEST(ImplicitCoupling, SerialExplicitDivergesAndSerialImplicitConverges) {
  {
    const fs::path dir = fresh_directory("e2e_serial_explicit");
    write_fixed_point_case(dir, "coupling: {scheme: serial-explicit, first: left}\n");
    const auto r = cosim_run(dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto a_read = reads_per_window(dir / "run" / "right" / "a_read.csv");
    ASSERT_EQ(a_read.size(), 10u);
    // Window 1: left on b's initial 2 gives a = 2; then a_n = 2 - 1.5 a_{n-1}.
    double a = 2.0;
    for (std::size_t n = 0; n < a_read.size(); ++n, a = 2.0 - 1.5 * a)
      EXPECT_NEAR(a_read[n], a, 1e-12 * std::abs(a)) << "window " << n + 1;
    std::printf("serial-explicit: a read by right in window 10: %.6g (fixed point 0.8)\n",
                a_read.back());
  }
  for (const char* method : {"aitken", "iqn-ils"}) {
    const fs::path dir = fresh_directory(std::string("e2e_serial_implicit_") + method);
    write_fixed_point_case(dir, fmt::format(R"(coupling:
  scheme: serial-implicit
  first: left
  convergence: [{{field: left.b, relative: 1.0e-10}}, {{field: right.a, relative: 1.0e-10}}]
  acceleration: {{method: {}}}
)",
                                            method));
    const auto r = cosim_run(dir);
    ASSERT_EQ(r.exit_code, 0) << method << "\n" << r.output;
    const auto a_read = reads_per_window(dir / "run" / "right" / "a_read.csv");
    const auto b_read = reads_per_window(dir / "run" / "left" / "b_read.csv");
    ASSERT_EQ(a_read.size(), 10u);
    ASSERT_EQ(b_read.size(), 10u);
    EXPECT_NEAR(a_read.back(), a_exact, 1e-8) << method;
    EXPECT_NEAR(b_read.back(), b_exact, 1e-8) << method;
    const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
    const double median = summary["coupling"]["median_iterations_per_window"].get<double>();
    const int most = summary["coupling"]["max_iterations_per_window"].get<int>();
    std::printf("serial-implicit %s: median %.1f, max %d iterations per window\n", method, median,
                most);
    EXPECT_EQ(summary["coupling"]["scheme"], "serial-implicit");
    EXPECT_LE(median, 5.0) << method;
  }
}

struct BadCoupling {
  const char* coupling;
  const char* location;
  const char* message;
};

TEST(ImplicitCoupling, BadCouplingBlocksAreRefusedAtTheirKeys) {
  const std::vector<BadCoupling> cases{
      {"coupling:\n  scheme: parallel-implicit\n  convergence: [{field: right.c, relative: "
       "1e-6}]\n",
       "job.yaml:24:25", "the coupler sends participant 'right' no field 'c' (it sends: a)"},
      {"coupling:\n  scheme: parallel-implicit\n  convergence: [{field: right.a, relative: 0}]\n",
       "job.yaml:24:44", "relative"},
      {"coupling:\n  scheme: parallel-implicit\n  max_iterations: 0\n  convergence: [{field: "
       "right.a, relative: 1e-6}]\n",
       "job.yaml:24:19", "max_iterations"},
      {"coupling:\n  scheme: parallel-implicit\n", "job.yaml:22:1",
       "needs at least one convergence measure"},
      {"coupling:\n  convergence: [{field: right.a, relative: 1e-6}]\n", "job.yaml:23:3",
       "'convergence' applies to implicit schemes"},
      {"coupling:\n  scheme: parallel-implicit\n  convergence: [{field: right.a}]\n",
       "job.yaml:24:17", "needs a limit"},
      {"coupling:\n  scheme: parallel-implicit\n  convergence: [{field: nobody.a, absolute: 1}]\n",
       "job.yaml:24:25", "no participant named 'nobody'"},
      {"coupling:\n  scheme: serial-explicit\n  first: middle\n", "job.yaml:24:10",
       "no participant named 'middle'"},
      {"coupling:\n  first: left\n", "job.yaml:23:3", "'first' applies to serial schemes"},
      {"coupling:\n  time_interpolation: linear\n", "job.yaml:23:3",
       "which a parallel-explicit scheme does not have yet"},
      {"coupling:\n  scheme: serial-implicit\n  convergence: [{field: right.a, relative: "
       "1e-6}]\n  acceleration: {fields: [right.a]}\n",
       "job.yaml:25:26", "a serial scheme accelerates what the coupler sends the first"},
  };
  for (const BadCoupling& c : cases) {
    const fs::path dir = fresh_directory("e2e_implicit_bad");
    write_fixed_point_case(dir, c.coupling);
    const auto r = run({binary("cosim").string(), "validate", (dir / "job.yaml").string()},
                       std::chrono::seconds(30));
    EXPECT_EQ(r.exit_code, 2) << c.coupling << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.location)) << c.coupling;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.coupling;
  }
}

// --cosim-repeat-windows: the test participant standalone, each window run
// twice from its saved state, writes exactly what a plain run writes.
TEST(ImplicitCoupling, RepeatedStandaloneWindowsWriteWhatAPlainRunWrites) {
  const fs::path dir = fresh_directory("e2e_repeat_windows");
  write_text(dir / "p.yaml", R"(kind: test_participant
dt: 3.0e-3
end_time: 0.05
mesh: {dim: 1, origin: [0.0], spacing: [0.25], cells: [4]}
writes:
  - {name: u, unit: m/s, function: [0.5, 0, 0, 0, 0]}
reads:
  - {name: impulse, unit: kg m/s, quantity: extensive, time: integral}
dynamics: {velocity: u, impulse: impulse, bulk_density: 1000, body_force: [9.81]}
)");
  for (const char* name : {"plain", "repeated"}) {
    std::vector<std::string> args{binary("cosim_test_participant").string(), "--config",
                                  (dir / "p.yaml").string(), "--output", (dir / name).string()};
    if (std::string(name) == "repeated") args.push_back("--cosim-repeat-windows");
    const auto r = run(args, std::chrono::seconds(60));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  for (const char* file : {"u_after_exchange.csv", "impulse_read.csv", "impulse_applied.csv"})
    EXPECT_EQ(read_text(dir / "plain" / file), read_text(dir / "repeated" / file)) << file;
  EXPECT_GT(read_csv(dir / "plain" / "u_after_exchange.csv").size(), 0u);
}

}  // namespace
}  // namespace cosim::testing

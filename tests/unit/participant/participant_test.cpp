// The participant API on its own: standalone runs, sub-cycling bookkeeping,
// exact window integrals and usage errors. Coupled behaviour is covered end
// to end in tests/integration.

#include "cosim/participant.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "cosim/error.hpp"

namespace cosim {
namespace {

Mesh line_grid() {
  return Mesh{"grid", UniformGrid{1, {0, 0, 0}, {0.25, 1, 1}, {4, 1, 1}}};
}

FieldSpec field(const std::string& name, TimeTreatment time = TimeTreatment::state) {
  FieldSpec f;
  f.name = name;
  f.mesh = "grid";
  f.unit = "Pa";
  f.time = time;
  return f;
}

TEST(Participant, StandaloneRunsItsOwnScheduleAndReadsDefaults) {
  Participant p("soil", CouplingEndpoint{});
  EXPECT_FALSE(p.is_coupled());
  p.declare_mesh(line_grid());
  p.declare_read(field("pore_pressure"), 101325.0);
  p.declare_write(field("solid_velocity"));
  p.initialize(0.0, 1.0);
  int steps = 0;
  while (p.is_coupling_ongoing()) {
    EXPECT_EQ(p.read("pore_pressure"), std::vector<double>(4, 101325.0));
    p.write("solid_velocity", std::vector<double>(4, 1.0));
    p.advance(std::min(0.3, p.max_time_step()));
    ++steps;
  }
  EXPECT_EQ(steps, 4);  // 0.3, 0.3, 0.3, 0.1
  EXPECT_DOUBLE_EQ(p.time(), 1.0);
}

TEST(Participant, StandaloneWindowsSubCycleToTheirEndsExactly) {
  Participant p("water", CouplingEndpoint{});
  p.declare_mesh(line_grid());
  p.set_standalone_window(2.5e-3);
  p.initialize(0.0, 0.05);
  std::size_t windows_seen = 0;
  while (p.is_coupling_ongoing()) {
    const std::size_t w = p.window_index();
    p.advance(std::min(7e-4, p.max_time_step()));
    if (p.window_index() != w) {
      ++windows_seen;
      EXPECT_DOUBLE_EQ(p.time(), 2.5e-3 * static_cast<double>(windows_seen));
    }
  }
  EXPECT_EQ(windows_seen, 20u);
}

TEST(Participant, WindowEndsDoNotDriftOverManyWindows) {
  // 10^4 windows of 1 ms, each in a step and a remainder: every window ends
  // exactly at start + k * window, as the coupler computes it (a running sum
  // drifted by ~1e-12 s after 8000 windows, past the coupler's tolerance).
  Participant p("water", CouplingEndpoint{});
  p.declare_mesh(line_grid());
  p.set_standalone_window(1e-3);
  p.initialize(0.25, 10.25);
  std::size_t windows = 0;
  while (p.is_coupling_ongoing()) {
    p.advance(std::min(3.7e-4, p.max_time_step()));
    p.advance(p.max_time_step());
    ++windows;
    ASSERT_EQ(p.time(), 0.25 + static_cast<double>(windows) * 1e-3) << "window " << windows;
  }
  EXPECT_EQ(windows, 10000u);
}

TEST(Participant, ReadIncrementsAddUpExactlyToTheWindowIntegral) {
  // Standalone, the received integral is zero; the bookkeeping is the same,
  // so drive it through a declared default and check the shares' sum.
  Participant p("water", CouplingEndpoint{});
  p.declare_mesh(line_grid());
  p.declare_read(field("impulse", TimeTreatment::integral));
  p.set_standalone_window(1.0);
  p.initialize(0.0, 1.0);
  std::vector<double> share(4), total(4, 0.0);
  while (p.is_coupling_ongoing()) {
    const double dt = std::min(0.3, p.max_time_step());
    p.read_increment("impulse", dt, share);
    for (std::size_t i = 0; i < 4; ++i) total[i] += share[i];
    p.advance(dt);
  }
  EXPECT_EQ(total, std::vector<double>(4, 0.0));
}

TEST(Participant, UsageErrorsAreReportedNotIgnored) {
  Participant p("soil", CouplingEndpoint{});
  p.declare_mesh(line_grid());
  EXPECT_THROW(p.declare_mesh(line_grid()), Error);  // twice
  FieldSpec on_unknown_mesh = field("x");
  on_unknown_mesh.mesh = "nope";
  EXPECT_THROW(p.declare_write(on_unknown_mesh), Error);
  p.declare_write(field("u"));
  EXPECT_THROW(p.declare_read(field("u")), Error);            // declared twice
  EXPECT_THROW(p.write("u", std::vector<double>(3)), Error);  // wrong size
  EXPECT_THROW(p.write("v", std::vector<double>(4)), Error);  // undeclared
  p.initialize(0.0, 1.0);
  EXPECT_THROW(p.declare_write(field("late")), Error);
  EXPECT_THROW(p.advance(2.0), Error);  // overshoots the window
  EXPECT_THROW(p.advance(-1.0), NumericalError);
  std::vector<double> out(4);
  EXPECT_THROW(p.read_increment("u", 0.1, out), Error);  // not an integral field read
}

// --cosim-repeat-windows runs each window twice: the solver is asked to save
// at every window's start, to restore after the first attempt, and may write
// its outputs only after the second. A toy solver state (a step counter and a
// running sum) shows the repeated run ends exactly where a plain one does.
TEST(Participant, RepeatedWindowsRestartFromTheSavedStateAndCompleteOnce) {
  struct State {
    int steps = 0;
    double sum = 0.0;
  };
  const auto run = [](bool repeat) {
    CouplingEndpoint endpoint;
    endpoint.repeat_windows = repeat;
    Participant p("soil", endpoint);
    p.declare_mesh(line_grid());
    p.declare_repeatable();
    p.set_standalone_window(0.25);
    p.initialize(0.0, 1.0);
    State state, saved;
    int saves = 0, restores = 0, completed = 0;
    std::vector<std::size_t> attempts;
    EXPECT_EQ(p.must_save_state(), repeat);
    while (p.is_coupling_ongoing()) {
      if (p.must_save_state()) {
        saved = state;
        ++saves;
      }
      attempts.push_back(p.iteration());
      const double dt = std::min(0.1, p.max_time_step());
      ++state.steps;
      state.sum += p.time() + dt;
      p.advance(dt);
      if (p.must_restore_state()) {
        EXPECT_FALSE(p.is_window_complete());
        state = saved;
        ++restores;
        EXPECT_DOUBLE_EQ(p.time(), 0.25 * static_cast<double>(p.window_index() - 1));
      }
      if (p.is_window_complete()) ++completed;
    }
    EXPECT_EQ(completed, 4);
    EXPECT_EQ(restores, repeat ? 4 : 0);
    EXPECT_EQ(saves, repeat ? 4 : 0);
    EXPECT_EQ(p.timings().windows, 4u);
    EXPECT_EQ(p.timings().iterations, repeat ? 8u : 4u);
    EXPECT_EQ(std::count(attempts.begin(), attempts.end(), 2u),
              repeat ? 12 : 0);  // steps of a second attempt
    return std::pair{state.steps, state.sum};
  };
  const auto plain = run(false);
  const auto repeated = run(true);
  EXPECT_EQ(plain.first, 12);  // 0.1, 0.1, 0.05 per window
  EXPECT_EQ(repeated.first, plain.first);
  EXPECT_EQ(repeated.second, plain.second);
}

TEST(Participant, RepeatingWindowsNeedsASolverThatDeclaresIt) {
  CouplingEndpoint endpoint;
  endpoint.repeat_windows = true;
  Participant p("soil", endpoint);
  p.declare_mesh(line_grid());
  EXPECT_THROW(p.initialize(0.0, 1.0), Error);
  Participant late("soil", CouplingEndpoint{});
  late.declare_mesh(line_grid());
  late.initialize(0.0, 1.0);
  EXPECT_THROW(late.declare_repeatable(), Error);
  EXPECT_FALSE(late.must_save_state());  // explicit and standalone: nothing to save
}

TEST(Participant, ReadsAheadInsideTheWindowOnly) {
  Participant p("soil", CouplingEndpoint{});
  p.declare_mesh(line_grid());
  p.declare_read(field("pore_pressure"), 5.0);
  p.set_standalone_window(0.5);
  p.initialize(0.0, 1.0);
  std::vector<double> values(4);
  p.read("pore_pressure", values, 0.5);
  EXPECT_EQ(values, std::vector<double>(4, 5.0));
  EXPECT_THROW(p.read("pore_pressure", values, 0.6), Error);
  EXPECT_THROW(p.read("pore_pressure", values, -0.1), Error);
}

TEST(Participant, MeshesAreValidatedWhenDeclared) {
  Participant p("soil", CouplingEndpoint{});
  EXPECT_THROW(p.declare_mesh(Mesh{"bad", UniformGrid{2, {0, 0, 0}, {0, 1, 1}, {2, 2, 1}}}),
               InputError);
}

// A rank's part of a mesh: its fields hold the part's values; a part that
// names an element outside the mesh or twice, or a cloud's part that does
// not name each of its points, is a usage error.
TEST(Participant, AMeshPartSizesTheFieldsAndIsChecked) {
  const UniformGrid grid{2, {0, 0, 0}, {1, 1, 1}, {4, 3, 1}};
  const MeshPart part = MeshPart::box(grid, {1, 1, 0}, {3, 3, 1});
  EXPECT_EQ(part.elements, (std::vector<std::int64_t>{5, 6, 9, 10}));
  Participant p("soil", CouplingEndpoint{});
  p.declare_mesh(Mesh{"grid", grid}, part);
  p.declare_write(field("solid_velocity"));
  EXPECT_EQ(p.field_size("solid_velocity"), 4u);

  Participant q("soil", CouplingEndpoint{});
  EXPECT_THROW(q.declare_mesh(Mesh{"grid", grid}, MeshPart{{0, 12}}), Error);
  EXPECT_THROW(q.declare_mesh(Mesh{"grid", grid}, MeshPart{{3, 3}}), Error);
  const PointCloud cloud{2, {0.5, 0.5, 1.5, 0.5}, {0.1, 0.1}};
  EXPECT_THROW(q.declare_mesh(Mesh{"points", cloud}, MeshPart{{7}}), Error);
  EXPECT_THROW(MeshPart::box(grid, {0, 0, 0}, {5, 1, 1}), std::invalid_argument);
  // A block with a ghost column: its fields hold the ghosts too.
  const MeshPart ghosted = MeshPart::box(grid, {0, 0, 0}, {3, 3, 1}, {0, 0, 0}, {2, 3, 1});
  EXPECT_EQ(ghosted.size(), 9u);
  EXPECT_TRUE(ghosted.has_ghosts());
  EXPECT_FALSE(ghosted.owns(2));
  EXPECT_TRUE(ghosted.owns(4));
  Participant r("soil", CouplingEndpoint{});
  r.declare_mesh(Mesh{"grid", grid}, ghosted);
  r.declare_read(field("pore_pressure"));
  EXPECT_EQ(r.field_size("pore_pressure"), 9u);
  EXPECT_THROW(r.declare_mesh(Mesh{"points", cloud}, MeshPart{{0, 1}, {1, 0}}), Error);
}

// A cloud's part changes size when points move to another rank: the fields
// on it follow, a state read holding zeros until the next exchange.
TEST(Participant, ACloudsPartMayChangeSize) {
  Participant p("soil", CouplingEndpoint{});
  p.declare_mesh(Mesh{"points", PointCloud{1, {0.5, 1.5}, {1.0, 1.0}}}, MeshPart{{4, 9}});
  FieldSpec v = field("solid_velocity");
  v.mesh = "points";
  FieldSpec pressure = field("pore_pressure");
  pressure.mesh = "points";
  p.declare_write(v);
  p.declare_read(pressure, 5.0);
  p.initialize(0.0, 1.0);
  p.update_mesh(Mesh{"points", PointCloud{1, {0.5, 1.5, 2.5}, {1.0, 1.0, 1.0}}},
                MeshPart{{4, 9, 2}});
  EXPECT_EQ(p.field_size("solid_velocity"), 3u);
  EXPECT_EQ(p.read("pore_pressure"), std::vector<double>(3, 0.0));
  p.write("solid_velocity", std::vector<double>(3, 1.0));
  EXPECT_THROW(p.update_mesh(Mesh{"grid", line_grid().geometry}, MeshPart{{0}}), Error);
}

}  // namespace
}  // namespace cosim

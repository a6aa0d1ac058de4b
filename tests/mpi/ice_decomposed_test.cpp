// The ICE solver decomposed over 1 to 4 ranks (mpirun, label mpi), its
// pressure solved by PETSc: every rank also runs the whole grid on its own
// with the built-in solver, and its owned cells must agree with the whole
// grid's to the linear solvers' tolerance after every step; the totals
// reduced over the ranks agree to round-off. Ghost layers fewer than a
// step's reach spoil the owned cells (the comparison can fail), and blocks
// narrower than the ghosts are refused.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cosim/error.hpp"
#include "ice/case/load_case.hpp"
#include "ice/case/make_solver.hpp"
#include "ice/parallel/mpi_block_link.hpp"

namespace ice::parallel {
namespace {
// Smagorinsky's eddy viscosity reaches a cell further than the plain
// viscous stress.
constexpr const char* turbulent = R"(  turbulence: {model: smagorinsky}
)";

class PetscEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { library_ = std::make_unique<PetscLibrary>(); }
  void TearDown() override { library_.reset(); }

 private:
  std::unique_ptr<PetscLibrary> library_;
};
const auto* const petsc_environment =
    ::testing::AddGlobalTestEnvironment(new PetscEnvironment);  // NOLINT: gtest owns it

int world_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

// Martin & Moyce's water column collapsing in air (viscous, a fixed
// pressure on top), colder than the air and conducting heat, on a coarse
// grid: the surge and the heat cross the blocks' edges.
std::string dam_break(int nx, int ny, const std::string& more = "") {
  return fmt::format(R"(kind: ice_case
name: dam_break
dimension: 2
grid: {{origin: [0.0, 0.0], upper: [0.28575, 0.142875], cells: [{}, {}]}}
gravity: [0.0, -9.81]
end_time: 0.19
materials:
  water:
    eos: {{type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}}
    viscosity: 1.0e-3
    thermal_conductivity: 0.6
  air:
    eos: {{type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}}
    viscosity: 1.8e-5
    thermal_conductivity: 0.025
exchange:
  - {{materials: [water, air], momentum: 1.0e15}}
initial:
  fill: air
  pressure: hydrostatic
  temperature: 293.15
  regions:
    - {{box: {{lower: [0.0, 0.0], upper: [0.1, 0.1143]}}, fill: water, temperature: 283.15}}
boundaries:
  y_max: {{type: fixed_pressure, pressure: 101325}}
numerics:
  pressure: {{tolerance: 1.0e-13}}
{})",
                     nx, ny, more);
}

struct Agreement {
  double worst = 0.0;  // max over steps and fields of |decomposed - whole| / scale
  double mass = 0.0;   // max relative difference of the total masses
  double time_step = 0.0;
  double water_speed = 0.0;  // the whole grid's largest |u_x| of the water at the end
  double time = 0.0;
};

// Steps the whole grid and the decomposed one with the whole grid's time
// steps; compares the owned cells' pressure, velocities, bulk densities and
// temperatures (relative to each field's largest magnitude).
template <int Dim = 2>
Agreement compare(const CaseDescription& c, int steps, int ghosts,
                  const std::string& preconditioner = "boomeramg") {
  auto whole = make_solver<Dim>(c);
  PetscPressureOptions pressure;
  pressure.tolerance = 1e-13;
  pressure.preconditioner = preconditioner;
  BlockSolver<Dim> block = make_block_solver<Dim>(MPI_COMM_WORLD, c, pressure, ghosts);
  const auto offset = block.link->offset();
  const std::vector<unsigned char>& owned = block.solver->owned_cells();
  Agreement a;
  // Relative to the field's largest magnitude, or for a velocity component
  // the largest of any component (a component that stays zero but for
  // round-off has no scale of its own).
  const auto difference = [&](const CellField& mine, const CellField& reference,
                              double floor = 0.0) {
    double scale = floor;
    for (double v : reference) scale = std::max(scale, std::abs(v));
    double worst = 0.0;
    for (int cell = 0; cell < block.solver->grid().cell_count(); ++cell) {
      if (owned[static_cast<std::size_t>(cell)] == 0) continue;
      auto ijk = block.solver->grid().cell_ijk(cell);
      for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) ijk[d] += offset[d];
      const double r = reference[static_cast<std::size_t>(whole->grid().cell(ijk))];
      worst = std::max(worst, std::abs(mine[static_cast<std::size_t>(cell)] - r) / scale);
    }
    return worst;
  };
  double dt = 1e-5;  // then growing by at most 1.2 a step, as ice_fluid's steps do
  for (int step = 0; step < steps; ++step) {
    const double stable = whole->stable_time_step(0.4, false);
    const double block_stable = block.solver->stable_time_step(0.4, false);
    if (step > 0) {
      a.time_step = std::max(a.time_step, std::abs(block_stable - stable) / stable);
      dt = std::min(stable, 1.2 * dt);
    }
    const StepReport report = whole->advance(dt);
    const StepReport block_report = block.solver->advance(dt);
    EXPECT_EQ(report.accepted, block_report.accepted);
    a.worst =
        std::max(a.worst, difference(block.solver->state().pressure, whole->state().pressure));
    for (std::size_t m = 0; m < 2; ++m) {
      const auto& mine = block.solver->state().materials[m];
      const auto& reference = whole->state().materials[m];
      a.worst = std::max({a.worst, difference(mine.bulk_density, reference.bulk_density),
                          difference(mine.temperature, reference.temperature)});
      double speed = 0.0;
      for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
        for (double u : reference.velocity[d]) speed = std::max(speed, std::abs(u));
      for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
        a.worst = std::max(a.worst, difference(mine.velocity[d], reference.velocity[d], speed));
    }
  }
  double speed = 0.0;
  for (double u : whole->state().materials[0].velocity[0]) speed = std::max(speed, std::abs(u));
  a.water_speed = speed;
  a.time = whole->time();
  const auto totals = whole->totals();
  const auto block_totals = block.solver->totals();
  for (std::size_t m = 0; m < 2; ++m)
    a.mass = std::max(a.mass, std::abs(block_totals[m].mass - totals[m].mass) / totals[m].mass);
  return a;
}

void expect_agreement(const std::string& name, const std::string& more,
                      const std::string& preconditioner = "boomeramg") {
  const CaseDescription c = load_case_text(dam_break(48, 24, more), "dam_break.yaml");
  const Agreement a = compare(c, 40, ghost_layers, preconditioner);
  double worst = a.worst, mass = a.mass, time_step = a.time_step;
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &mass, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &time_step, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (world_rank() == 0)
    std::printf(
        "ICE %s 48 x 24, 40 steps to t = %.3g s (the surge at %.3g m/s): worst relative "
        "difference %.3g (tolerance 1e-8), total mass %.3g (1e-12), stable time step "
        "%.3g (1e-9)\n",
        name.c_str(), a.time, a.water_speed, worst, mass, time_step);
  EXPECT_LT(worst, 1e-8) << name;
  EXPECT_LT(mass, 1e-12) << name;
  EXPECT_LT(time_step, 1e-9) << name;
}

TEST(IceDecomposed, OwnedCellsAgreeWithTheWholeGridToTheSolversTolerance) {
  expect_agreement("viscous", "");
  expect_agreement("turbulent", turbulent);
  // hypre's structured multigrid across the blocks (the default in 2D and 3D).
  expect_agreement("viscous, pfmg", "", "pfmg");
}

// The same in 3D: the water column across the width of a box, 20 x 12 x 12
// cells, on the process grid with the least halo for 1 to 4 ranks.
TEST(IceDecomposed, OwnedCellsAgreeInThreeDimensions) {
  std::string text = dam_break(20, 12);
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"dimension: 2", "dimension: 3"},
        {"origin: [0.0, 0.0], upper: [0.28575, 0.142875], cells: [20, 12]",
         "origin: [0.0, 0.0, 0.0], upper: [0.28575, 0.142875, 0.142875], cells: [20, 12, 12]"},
        {"gravity: [0.0, -9.81]", "gravity: [0.0, -9.81, 0.0]"},
        {"lower: [0.0, 0.0], upper: [0.1, 0.1143]",
         "lower: [0.0, 0.0, 0.0], upper: [0.1, 0.1143, 0.142875]"}}) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  const CaseDescription c = load_case_text(text, "dam_break_3d.yaml");
  for (const char* preconditioner : {"boomeramg", "pfmg"}) {
    const Agreement a = compare<3>(c, 20, ghost_layers, preconditioner);
    double worst = a.worst, mass = a.mass;
    MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &mass, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (world_rank() == 0)
      std::printf(
          "ICE 3D 20 x 12 x 12 (%s), 20 steps to t = %.3g s (the surge at %.3g m/s): worst "
          "relative difference %.3g (tolerance 1e-8), total mass %.3g (1e-12)\n",
          preconditioner, a.time, a.water_speed, worst, mass);
    EXPECT_GT(a.water_speed, 0.0) << preconditioner;
    EXPECT_LT(worst, 1e-8) << preconditioner;
    EXPECT_LT(mass, 1e-12) << preconditioner;
  }
}

TEST(IceDecomposed, TooFewGhostLayersSpoilTheOwnedCells) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (ranks == 1) return;  // one block has no neighbour to spoil it
  const CaseDescription c = load_case_text(dam_break(48, 24, turbulent), "dam_break.yaml");
  double worst = 0.0;
  try {
    worst = compare(c, 40, 2).worst;
  } catch (const cosim::NumericalError&) {
    worst = 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(worst, 1e-6);
}

TEST(IceDecomposed, RefusesBlocksNarrowerThanTheGhostLayers) {
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const CaseDescription c = load_case_text(dam_break(ranks * (ghost_layers - 1), 1), "narrow.yaml");
  if (ranks == 1) {
    EXPECT_NO_THROW(make_block_solver<2>(MPI_COMM_WORLD, c, PetscPressureOptions{}));
  } else {
    EXPECT_THROW(make_block_solver<2>(MPI_COMM_WORLD, c, PetscPressureOptions{}),
                 cosim::InputError);
  }
}

}  // namespace
}  // namespace ice::parallel

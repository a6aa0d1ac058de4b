#include "ice/case/load_case.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <utility>

#include "cosim/error.hpp"
#include "ice/case/case_schema.hpp"
#include "ice/case/make_solver.hpp"
#include "input_error.hpp"
#include "replaced_text.hpp"

using cosim::testing::replaced;

namespace ice {
namespace {

const std::string dam_break = R"(kind: ice_case
name: dam
dimension: 2
grid: {origin: [0.0, 0.0], upper: [0.4, 0.2], cells: [8, 4]}
gravity: [0.0, -9.81]
end_time: 0.3
materials:
  water:
    eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}
    viscosity: 1.0e-3
  air:
    eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}
exchange:
  - {materials: [water, air], momentum: 1.0e15, heat: 1.0e3}
initial:
  fill: air
  temperature: 300
  regions:
    - {box: {lower: [0.0, 0.0], upper: [0.1, 0.1]}, fill: water}
    - {sphere: {centre: [0.3, 0.15], radius: 0.03}, fill: water, velocity: [0.0, -1.0]}
boundaries:
  x_max: outflow
  y_max: {type: fixed_pressure, pressure: 101325, temperature: 300}
numerics:
  cfl: 0.3
  limiter: minmod
  pressure: {tolerance: 1.0e-9, preconditioner: incomplete_cholesky}
output:
  every: 0.05
  gauges: [{name: g1, point: [0.2, 0.01]}]
coupling: {drag: ice, minimum_porosity: 0.1, heat_exchange: true}
)";

std::string error_of(const std::string& text) {
  return cosim::testing::input_error_message([&] { load_case_text(text, "case.yaml"); });
}

TEST(IceCase, ReadsEveryKeyAndTheDefaults) {
  const CaseDescription c = load_case_text(dam_break, "case.yaml");
  EXPECT_EQ(c.name, "dam");
  EXPECT_EQ(c.dimension, 2);
  EXPECT_EQ(c.cells[0], 8);
  EXPECT_DOUBLE_EQ(c.gravity[1], -9.81);
  ASSERT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.materials[0].name, "water");  // file order
  EXPECT_EQ(c.materials[1].name, "air");
  EXPECT_DOUBLE_EQ(c.materials[0].viscosity, 1e-3);
  EXPECT_DOUBLE_EQ(c.exchange.momentum[1], 1e15);
  EXPECT_DOUBLE_EQ(c.exchange.heat[2], 1e3);
  EXPECT_EQ(c.initial.fill, 1);
  EXPECT_FALSE(c.initial.pressure.has_value());  // hydrostatic by default
  ASSERT_EQ(c.initial.regions.size(), 2u);
  EXPECT_EQ(c.initial.regions[1].shape, Region::Shape::sphere);
  EXPECT_DOUBLE_EQ((*c.initial.regions[1].velocity)[1], -1.0);
  ASSERT_EQ(c.sides.size(), 4u);
  EXPECT_EQ(c.sides[0].type, SideType::wall);
  EXPECT_EQ(c.sides[1].type, SideType::outflow);
  EXPECT_EQ(c.sides[3].type, SideType::fixed_pressure);
  EXPECT_DOUBLE_EQ(*c.sides[3].temperature, 300.0);
  EXPECT_DOUBLE_EQ(c.numerics.cfl, 0.3);
  EXPECT_EQ(c.numerics.limiter, Limiter::minmod);
  EXPECT_EQ(c.numerics.pressure.preconditioner, PressurePreconditioner::incomplete_cholesky);
  EXPECT_DOUBLE_EQ(c.numerics.max_step_growth, 1.2);
  EXPECT_DOUBLE_EQ(c.initial.minimum_volume_fraction, 1e-6);
  ASSERT_EQ(c.gauges.size(), 1u);
  EXPECT_NE(c.config_hash, 0u);
  // A wave gauge's vertical is the axis gravity lies along; its material water.
  const CaseDescription waves =
      load_case_text(replaced(dam_break, "gauges: [{name: g1, point: [0.2, 0.01]}]",
                              "wave_gauges: [{name: w, point: [0.2, 0.5]}]"),
                     "case.yaml");
  ASSERT_EQ(waves.wave_gauges.size(), 1u);
  EXPECT_EQ(waves.wave_gauges[0].vertical, 1);
  EXPECT_EQ(waves.wave_gauges[0].material, "water");
  EXPECT_NE(error_of(replaced(replaced(dam_break, "gravity: [0.0, -9.81]\n", ""),
                              "gauges: [{name: g1, point: [0.2, 0.01]}]",
                              "wave_gauges: [{name: w, point: [0.2, 0.5]}]"))
                .find("needs gravity along an axis"),
            std::string::npos);
  EXPECT_TRUE(c.coupling.drag_in_solver);
  EXPECT_DOUBLE_EQ(c.coupling.minimum_porosity, 0.1);
  EXPECT_DOUBLE_EQ(c.coupling.drag_viscosity, 0.0);
  EXPECT_TRUE(c.coupling.heat_exchange);
  EXPECT_FALSE(
      load_case_text(replaced(dam_break, "drag: ice, ", ""), "case.yaml").coupling.drag_in_solver);
  EXPECT_FALSE(c.numerics.pressure_solver);  // built-in on one process, PETSc on several ranks
  const CaseDescription petsc = load_case_text(
      replaced(
          dam_break, "preconditioner: incomplete_cholesky",
          "solver: petsc, preconditioner: boomeramg, petsc_options: \"-ice_pressure_ksp_view\""),
      "case.yaml");
  EXPECT_EQ(petsc.numerics.pressure_solver, NumericsDescription::PressureSolverKind::petsc);
  EXPECT_EQ(petsc.numerics.petsc_preconditioner, "boomeramg");
  EXPECT_EQ(petsc.numerics.petsc_options, "-ice_pressure_ksp_view");
  // hypre's structured multigrid: the default of a 2D grid with PETSc.
  EXPECT_EQ(c.numerics.petsc_preconditioner, "pfmg");
  EXPECT_EQ(load_case_text(replaced(dam_break, "preconditioner: incomplete_cholesky",
                                    "solver: petsc, preconditioner: pfmg"),
                           "case.yaml")
                .numerics.petsc_preconditioner,
            "pfmg");
  const auto solver = make_solver<2>(c);
  EXPECT_GT(solver->state().materials[0].volume_fraction[0], 0.99);  // water in the corner
  EXPECT_LT(solver->state().materials[0].volume_fraction[7], 1e-5);
  EXPECT_THROW(make_solver<1>(c), std::invalid_argument);
}

// A block's fill (what a rank of a decomposed run computes instead of the
// whole grid's): the whole fill's values in the block's cells, bit for bit,
// the hydrostatic pressure marched down the block's whole columns.
TEST(IceCase, TheFillOfABlockIsThatOfTheWholeGridInItsCells) {
  const CaseDescription c = load_case_text(dam_break, "case.yaml");
  const CellGrid<2> grid = case_grid<2>(c);
  const CellFill<2> whole = case_fill<2>(c, grid);
  const std::array<int, 2> first{3, 1}, count{4, 2};
  const auto [box_first, box_count] = fill_box_along_gravity<2>(c, grid, first, count);
  EXPECT_EQ(box_first, (std::array<int, 2>{3, 0}));  // whole along gravity (y)
  EXPECT_EQ(box_count, (std::array<int, 2>{4, 4}));
  const CellFill<2> box = case_fill<2>(c, grid, box_first, box_count);
  ASSERT_EQ(box.pressure.size(), 16u);
  for (int j = 0; j < box_count[1]; ++j)
    for (int i = 0; i < box_count[0]; ++i) {
      const auto k = static_cast<std::size_t>(i + box_count[0] * j);
      const auto w = static_cast<std::size_t>(grid.cell({i + box_first[0], j + box_first[1]}));
      EXPECT_EQ(box.material[k], whole.material[w]);
      EXPECT_EQ(box.pressure[k], whole.pressure[w]);
      EXPECT_EQ(box.velocity[1][k], whole.velocity[1][w]);
    }
  // A given pressure needs no columns: the block alone.
  const CaseDescription given = load_case_text(
      replaced(dam_break, "  temperature: 300\n", "  temperature: 300\n  pressure: 101325\n"),
      "case.yaml");
  EXPECT_EQ(fill_box_along_gravity<2>(given, grid, first, count), std::pair(first, count));
}

TEST(IceCase, ErrorsNameTheKeyAndTheLine) {
  const struct {
    std::string from, to, expected;
  } cases[] = {
      {"dimension: 2", "dimension: 4", "dimension"},
      {"upper: [0.4, 0.2]", "upper: [0.4]", "grid.upper"},
      {"upper: [0.4, 0.2]", "upper: [-0.4, 0.2]", "not above the origin"},
      {"cells: [8, 4]", "cells: [8, 0.5]", "whole number"},
      {"fill: air\n", "fill: steam\n", "unknown material 'steam'"},
      {"materials: [water, air]", "materials: [water, water]", "with itself"},
      {"momentum: 1.0e15", "momentum: -1.0", "momentum"},
      {"viscosity: 1.0e-3", "viscosity: -1.0e-3", "viscosity"},
      {"bulk_modulus: 2.15e9", "bulk_modulu: 2.15e9", "bulk_modulu"},
      {"upper: [0.1, 0.1]}", "upper: [-0.1, 0.1]}", "upper corner"},
      {"lower: [0.0, 0.0], upper: [0.1, 0.1]", "lower: [1.0, 0.0], upper: [2.0, 0.1]",
       "outside the domain"},
      {"x_max: outflow", "z_max: outflow", "does not exist in a 2D case"},
      {"type: fixed_pressure, pressure: 101325,", "type: fixed_pressure,", "needs `pressure`"},
      {"x_max: outflow", "x_max: {type: inflow}", "needs `velocity`"},
      {"cfl: 0.3", "cfl: 3.0", "cfl"},
      {"point: [0.2, 0.01]", "point: [0.5, 0.01]", "outside the domain"},
      {"end_time: 0.3", "end_time: 0.0", "end_time"},
      {"temperature: 300\n", "temperature: 300\n  pressure: 1.0e5\n", "no error"},
      {"fill: water, velocity", "fill: water, pressure: 2.0e5, velocity", "hydrostatic"},
      {"drag: ice", "drag: solid", "coupling.drag"},
      {"minimum_porosity: 0.1", "minimum_porosity: 0.0", "coupling.minimum_porosity"},
      {"minimum_porosity: 0.1,", "minimum_porosity: 0.1, drag_viscosity: 1.0e-3,",
       "coupling.drag_viscosity': scales each fluid's drag by its viscosity, and material 'air'"},
      {"minimum_porosity: 0.1,", "minimum_porosity: 0.1, drag_viscosity: -1.0,",
       "coupling.drag_viscosity"},
      {"gauges: [{name: g1, point: [0.2, 0.01]}]",
       "wave_gauges: [{name: w, point: [0.2, 0.0], material: oil}]", "no material 'oil'"},
      {"gauges: [{name: g1, point: [0.2, 0.01]}]", "wave_gauges: [{name: w, point: [0.5, 0.0]}]",
       "outside the domain along x"},
      {"preconditioner: incomplete_cholesky", "preconditioner: gamg",
       "numerics.pressure.preconditioner': 'gamg' is PETSc's: it needs `solver: petsc`"},
      {"preconditioner: incomplete_cholesky", "preconditioner: incomplete_cholesky, solver: petsc",
       "'incomplete_cholesky' is the built-in solver's"},
      {"preconditioner: incomplete_cholesky",
       "preconditioner: jacobi, solver: builtin, petsc_options: \"-ice_pressure_ksp_monitor\"",
       "numerics.pressure.petsc_options"},
      {"preconditioner: incomplete_cholesky", "solver: hypre", "numerics.pressure.solver"},
  };
  for (const auto& c : cases) {
    const std::string message = error_of(replaced(dam_break, c.from, c.to));
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.to << " -> " << message;
    if (c.expected != "no error") {
      EXPECT_NE(message.find("case.yaml:"), std::string::npos) << message;
    }
  }
}

TEST(IceCase, HelpListsEveryTopLevelKeyAndTheEquationsOfState) {
  const std::string help = ice_case_help();
  for (const char* key : {"grid", "gravity", "end_time", "materials", "exchange", "initial",
                          "boundaries", "numerics", "output", "ideal_gas", "linear_water"}) {
    EXPECT_NE(help.find(key), std::string::npos) << key;
  }
}

}  // namespace
}  // namespace ice

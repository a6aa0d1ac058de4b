// The ice_case schema is the one place a default is stated: every default is
// a value its own key accepts, a case that leaves a key out reads it, and the
// description built in code starts from the same values.

#include <gtest/gtest.h>

#include <string>

#include "cosim/error.hpp"
#include "ice/advection/limiter.hpp"
#include "ice/case/case_schema.hpp"
#include "ice/case/load_case.hpp"
#include "ice/pressure/pressure_solver.hpp"
#include "schema_default.hpp"

namespace ice {
namespace {

template <class T>
T schema_default(const std::string& key_path) {
  return cosim::testing::schema_default<T>(ice_case_schema(), key_path);
}

const char* const bare_case = R"(kind: ice_case
name: bare
dimension: 1
grid: {origin: [0.0], upper: [1.0], cells: [10]}
end_time: 0.1
materials:
  air: {eos: {type: ideal_gas, gas_constant: 287.0, heat_capacity_ratio: 1.4}}
  water: {eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8}}
exchange:
  - {materials: [air, water]}
initial: {fill: air}
numerics: {turbulence: {model: smagorinsky}}
)";

TEST(IceCaseSchemaDefaults, EveryDefaultIsAcceptedByItsKey) {
  EXPECT_NO_THROW(ice_case_schema().check_defaults());
}

TEST(IceCaseSchemaDefaults, ACaseWithoutTheOptionalKeysReadsTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  ASSERT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.materials[0].viscosity, schema_default<double>("materials.<name>.viscosity"));
  EXPECT_EQ(c.materials[0].thermal_conductivity,
            schema_default<double>("materials.<name>.thermal_conductivity"));
  EXPECT_EQ(c.exchange.momentum[1], schema_default<double>("exchange.[].momentum"));
  EXPECT_EQ(c.exchange.heat[1], schema_default<double>("exchange.[].heat"));
  EXPECT_EQ(c.initial.reference_pressure, schema_default<double>("initial.reference_pressure"));
  EXPECT_EQ(c.initial.temperature, schema_default<double>("initial.temperature"));
  EXPECT_EQ(c.initial.minimum_volume_fraction,
            schema_default<double>("initial.minimum_volume_fraction"));
  const NumericsDescription& n = c.numerics;
  EXPECT_EQ(n.cfl, schema_default<double>("numerics.cfl"));
  EXPECT_EQ(n.acoustic, schema_default<bool>("numerics.acoustic"));
  EXPECT_EQ(n.initial_time_step, schema_default<double>("numerics.initial_time_step"));
  EXPECT_EQ(n.min_time_step, schema_default<double>("numerics.min_time_step"));
  EXPECT_EQ(n.max_time_step, schema_default<double>("numerics.max_time_step"));
  EXPECT_EQ(n.max_step_growth, schema_default<double>("numerics.max_step_growth"));
  EXPECT_EQ(n.limiter, limiter_from_name(schema_default<std::string>("numerics.limiter")));
  EXPECT_EQ(n.pressure.tolerance, schema_default<double>("numerics.pressure.tolerance"));
  EXPECT_EQ(n.pressure.max_iterations, schema_default<int>("numerics.pressure.max_iterations"));
  // The preconditioner's default depends on the solver (schema text: multigrid built-in,
  // with PETSc pfmg in 2D and 3D, boomeramg in 1D); the solver's on the rank count.
  EXPECT_EQ(n.pressure.preconditioner, PressurePreconditioner::multigrid);
  EXPECT_EQ(n.petsc_preconditioner, "boomeramg");  // 1D: pfmg needs a 2D or 3D grid
  try {
    load_case_text(std::string(bare_case).replace(
                       std::string(bare_case).find("numerics: {"), 11,
                       "numerics: {pressure: {solver: petsc, preconditioner: pfmg}, "),
                   "bare.yaml");
    ADD_FAILURE() << "pfmg on a 1D grid was not refused";
  } catch (const cosim::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pfmg (hypre's structured multigrid) needs a 2D or 3D"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(n.pressure_solver);
  EXPECT_EQ(n.equilibration.tolerance, schema_default<double>("numerics.equilibration.tolerance"));
  EXPECT_EQ(n.equilibration.max_iterations,
            schema_default<int>("numerics.equilibration.max_iterations"));
  EXPECT_EQ(n.smagorinsky_constant, schema_default<double>("numerics.turbulence.constant"));
  EXPECT_EQ(c.window, schema_default<double>("window"));
  EXPECT_EQ(c.output_every, schema_default<double>("output.every"));
  EXPECT_EQ(c.snapshots, schema_default<bool>("output.snapshots"));
  EXPECT_EQ(c.gauge_every, schema_default<double>("output.gauge_every"));
  EXPECT_EQ(c.threads, schema_default<int>("threads"));
  EXPECT_EQ(c.coupling.drag_in_solver, schema_default<std::string>("coupling.drag") == "ice");
  EXPECT_EQ(c.coupling.minimum_porosity, schema_default<double>("coupling.minimum_porosity"));
  EXPECT_EQ(c.coupling.heat_exchange, schema_default<bool>("coupling.heat_exchange"));
}

TEST(IceCaseSchemaDefaults, TheDescriptionBuiltInCodeStartsFromTheSchemaDefaults) {
  const CaseDescription c = load_case_text(bare_case, "bare.yaml");
  const InitialDescription initial;
  EXPECT_EQ(initial.reference_pressure, c.initial.reference_pressure);
  EXPECT_EQ(initial.temperature, c.initial.temperature);
  EXPECT_EQ(initial.minimum_volume_fraction, c.initial.minimum_volume_fraction);
  const NumericsDescription n;
  EXPECT_EQ(n.cfl, c.numerics.cfl);
  EXPECT_EQ(n.acoustic, c.numerics.acoustic);
  EXPECT_EQ(n.initial_time_step, c.numerics.initial_time_step);
  EXPECT_EQ(n.min_time_step, c.numerics.min_time_step);
  EXPECT_EQ(n.max_time_step, c.numerics.max_time_step);
  EXPECT_EQ(n.max_step_growth, c.numerics.max_step_growth);
  EXPECT_EQ(n.limiter, c.numerics.limiter);
  EXPECT_EQ(n.pressure.tolerance, c.numerics.pressure.tolerance);
  EXPECT_EQ(n.pressure.max_iterations, c.numerics.pressure.max_iterations);
  EXPECT_EQ(n.pressure.preconditioner, c.numerics.pressure.preconditioner);
  EXPECT_EQ(n.equilibration.tolerance, c.numerics.equilibration.tolerance);
  EXPECT_EQ(n.equilibration.max_iterations, c.numerics.equilibration.max_iterations);
  const CaseDescription in_code;
  EXPECT_EQ(in_code.window, c.window);
  EXPECT_EQ(in_code.output_every, c.output_every);
  EXPECT_EQ(in_code.snapshots, c.snapshots);
  EXPECT_EQ(in_code.gauge_every, c.gauge_every);
  EXPECT_EQ(in_code.threads, c.threads);
  EXPECT_EQ(in_code.coupling.drag_in_solver, c.coupling.drag_in_solver);
  EXPECT_EQ(in_code.coupling.minimum_porosity, c.coupling.minimum_porosity);
  EXPECT_EQ(in_code.coupling.heat_exchange, c.coupling.heat_exchange);
}

}  // namespace
}  // namespace ice

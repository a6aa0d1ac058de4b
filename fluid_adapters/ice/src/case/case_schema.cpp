#include "ice/case/case_schema.hpp"

#include <limits>

#include "cosim/io/run_size.hpp"
#include "ice/advection/limiter.hpp"
#include "ice/eos/eos_registry.hpp"

namespace ice {

using cosim::config::Schema;

namespace {

Schema vector_schema(const char* unit) {
  return Schema::vector(1, 3).unit(unit);
}

Schema material_schema() {
  Schema material = Schema::object("A fluid material.");
  material
      .required("eos", Schema::any(),
                "Equation of state: {type: ideal_gas | linear_water, ...} (listed below).")
      .optional("viscosity", Schema::number().non_negative().unit("Pa s").default_value("0"),
                "Dynamic viscosity.")
      .optional("thermal_conductivity",
                Schema::number().non_negative().unit("W/(m K)").default_value("0"),
                "Thermal conductivity.");
  return material;
}

Schema exchange_schema() {
  Schema pair = Schema::object(
      "Exchange between two materials (Tran et al., MPMICE, eqs. 23, 48); in a cell the pair "
      "exchanges with K phi_a phi_b and H phi_a phi_b.");
  pair.required("materials", Schema::sequence(Schema::string().non_empty()).length(2, 2),
                "The two materials.")
      .optional("momentum", Schema::number().non_negative().unit("kg/(m^3 s)").default_value("0"),
                "Momentum exchange coefficient K; 1e15 makes the pair move as one.")
      .optional("heat", Schema::number().non_negative().unit("W/(m^3 K)").default_value("0"),
                "Heat exchange coefficient H.");
  return pair;
}

Schema region_schema() {
  Schema box = Schema::object("Axis-aligned box.");
  box.required("lower", vector_schema("m"), "Lower corner.")
      .required("upper", vector_schema("m"), "Upper corner.");
  Schema sphere = Schema::object("Sphere (disc in 2D, interval in 1D).");
  sphere.required("centre", vector_schema("m"), "Centre.")
      .required("radius", Schema::number().positive().unit("m"), "Radius.");
  Schema region = Schema::object("Cells whose centre lies in the shape; give `box` or `sphere`.");
  region.optional("box", box, "The region is a box.")
      .optional("sphere", sphere, "The region is a sphere.")
      .required("fill", Schema::string().non_empty(), "Material filling the region.")
      .optional("pressure", Schema::number().positive().unit("Pa"),
                "Pressure (not with a hydrostatic initial pressure).")
      .optional("temperature", Schema::number().positive().unit("K"), "Temperature.")
      .optional("velocity", vector_schema("m/s"), "Velocity.");
  return region;
}

Schema initial_schema() {
  Schema initial =
      Schema::object("The initial state: `fill` everywhere, then the regions in order.");
  initial.required("fill", Schema::string().non_empty(), "Material filling every other cell.")
      .optional(
          "pressure",
          Schema::any_of({Schema::number().positive(), Schema::one_of({"hydrostatic"})}),
          "Pressure [Pa], or `hydrostatic` (default): rho g h below `reference_pressure` on the "
          "side gravity points away from.")
      .optional("reference_pressure",
                Schema::number().positive().unit("Pa").default_value("101325"),
                "Pressure at the top of a hydrostatic column.")
      .optional("temperature", Schema::number().positive().unit("K").default_value("293.15"),
                "Temperature.")
      .optional("velocity", vector_schema("m/s").default_note("zero"), "Velocity.")
      .optional("regions", Schema::sequence(region_schema()), "Regions overriding the fill.")
      .optional("minimum_volume_fraction",
                Schema::number().range(1e-12, 1e-2).default_value("1e-6"),
                "Volume fraction every absent material keeps in a cell (ICE needs each material "
                "everywhere).");
  return initial;
}

Schema side_schema() {
  Schema side = Schema::object("A side with values.");
  side.required("type", Schema::one_of({"wall", "outflow", "fixed_pressure", "inflow"}),
                "wall: no flow, tangential velocity free; outflow: zero-gradient; fixed_pressure: "
                "P held on the face; inflow: the given velocity (what enters has the boundary "
                "cell's composition and temperature).")
      .optional("pressure", Schema::number().positive().unit("Pa"), "fixed_pressure: the pressure.")
      .optional("velocity", vector_schema("m/s"), "inflow: the velocity.")
      .optional("temperature", Schema::number().positive().unit("K"),
                "Temperature held on the side for heat conduction; default insulated.");
  return Schema::any_of({Schema::one_of({"wall", "outflow"}), side});
}

Schema boundaries_schema() {
  Schema b = Schema::object("Conditions per side; default wall.");
  for (const char* side : {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"})
    b.optional(side, side_schema(), "Condition on this side.");
  return b;
}

Schema numerics_schema() {
  Schema pressure = Schema::object("The implicit pressure solve (eq. 125).").default_value("{}");
  pressure
      .optional("tolerance", Schema::number().range(1e-14, 1e-2).default_value("1e-10"),
                "Relative residual of conjugate gradients.")
      .optional("max_iterations", Schema::integer().range(1, 1e6).default_value("2000"),
                "Iterations before a numerical failure (exit 4).")
      .optional("solver", Schema::one_of({"builtin", "petsc"}),
                "builtin: the solver's own conjugate gradients (one process); petsc: PETSc's, "
                "over every rank. Default: builtin on one process, petsc on several ranks.")
      .optional("preconditioner",
                Schema::one_of(
                    {"multigrid", "jacobi", "incomplete_cholesky", "pfmg", "boomeramg", "gamg"}),
                "Preconditioner of conjugate gradients. builtin: multigrid (default), jacobi or "
                "incomplete_cholesky; petsc: pfmg (default in 2D and 3D; hypre's structured "
                "multigrid across the ranks' blocks), boomeramg (default in 1D; hypre's "
                "algebraic multigrid), gamg (PETSc's) or jacobi.")
      .optional("petsc_options", Schema::string(),
                "With petsc: further PETSc options, prefix ice_pressure_ (e.g. "
                "\"-ice_pressure_ksp_monitor\").");
  Schema equilibration =
      Schema::object("The per-cell pressure equilibration (eqs. 42-43).").default_value("{}");
  equilibration
      .optional("tolerance", Schema::number().range(1e-15, 1e-3).default_value("1e-12"),
                "Relative tolerance on the filled pore volume.")
      .optional("max_iterations", Schema::integer().range(1, 1e4).default_value("100"),
                "Newton iterations before a numerical failure (exit 4).");
  Schema turbulence = Schema::object("Smagorinsky LES (eqs. 17-19).");
  turbulence.required("model", Schema::one_of({"smagorinsky"}), "The model.")
      .optional("constant", Schema::number().range(0.0, 1.0).default_value("0.17"), "C_s.");
  Schema numerics =
      Schema::object(
          "Time stepping and schemes. The step is dt = min(cfl / max_c sum_d (|U_d| [+ c]) / dx_d, "
          "max_step_growth * previous dt, max_time_step, time to the next output); a step whose "
          "face "
          "Courant number exceeds 1 is repeated with half the step.")
          .default_value("{}");
  numerics
      .optional("cfl", Schema::number().range(1e-3, 1.0).default_value("0.4"), "Courant number.")
      .optional("acoustic", Schema::boolean().default_value("false"),
                "Include the sound speed c in the step (resolves shocks; the implicit pressure is "
                "stable without it).")
      .optional("initial_time_step", Schema::number().positive().unit("s").default_value("1e-5"),
                "First step.")
      .optional("min_time_step", Schema::number().positive().unit("s").default_value("1e-10"),
                "A step the stability or refused steps bring below this ends the run as a "
                "numerical failure (exit 4), with the state it failed from as a last snapshot; "
                "a step cut short by a window end or an output time may be shorter.")
      .optional("max_time_step", Schema::number().non_negative().unit("s").default_value("0"),
                "Largest step; 0: none.")
      .optional("max_step_growth", Schema::number().range(1.0, 10.0).default_value("1.2"),
                "Largest ratio of one step to the previous.")
      .optional("limiter", Schema::one_of(limiter_names()).default_value("van_leer"),
                "Advection limiter (eqs. 77-80).")
      .optional("pressure", pressure, "Pressure solve.")
      .optional("equilibration", equilibration, "Pressure equilibration.")
      .optional("turbulence", Schema::any_of({Schema::one_of({"none"}), turbulence}),
                "none (default) or {model: smagorinsky, constant: C_s}.");
  return numerics;
}

Schema output_schema() {
  Schema gauge = Schema::object("A gauge: pressure, velocity and volume fractions at a point.");
  gauge.required("name", Schema::string().non_empty(), "Column suffix in gauges.csv.")
      .required("point", vector_schema("m"), "Position.");
  Schema wave_gauge = Schema::object(
      "A wave gauge: the height of a material's free surface over the vertical column of cells "
      "through a point (the vertical: the axis gravity lies along; pores count whole).");
  wave_gauge.required("name", Schema::string().non_empty(), "Column eta_<name> in gauges.csv.")
      .required("point", vector_schema("m"),
                "A point of the column (its vertical coordinate is ignored).")
      .optional("material", Schema::string().non_empty().default_value("water"),
                "The material whose surface it measures.");
  Schema output = Schema::object("What the run writes.").default_value("{}");
  output
      .optional("every", Schema::number().non_negative().unit("s").default_value("0"),
                "Snapshot interval; 0: start and end only.")
      .optional("snapshots", Schema::boolean().default_value("true"), "HDF5 + XDMF snapshots.")
      .optional("gauge_every", Schema::number().non_negative().unit("s").default_value("0"),
                "Gauge interval; 0: every step.")
      .optional("gauges", Schema::sequence(gauge), "Gauges (gauges.csv).")
      .optional("wave_gauges", Schema::sequence(wave_gauge),
                "Free-surface gauges (gauges.csv, eta_<name> [m]).");
  return output;
}

Schema coupling_schema() {
  Schema coupling =
      Schema::object(
          "How ice_fluid takes part in a coupled run with a porous solid on its mesh 'ice_cells' "
          "(ignored standalone).")
          .default_value("{}");
  coupling
      .optional("drag", Schema::one_of({"coupler", "ice"}).default_value("coupler"),
                "coupler: read the momentum the coupler's exchange gives the fluid "
                "(momentum_exchange_impulse); ice: solve the fluid-solid drag in every step "
                "with the solid as an exchange material (Tran et al., MPMICE, eqs. 48, 67-68), "
                "reading drag_coefficient and solid_bulk_density and writing the solid's "
                "momentum_exchange_impulse (the job's momentum_exchange.solved_by: fluid).")
      .optional("minimum_porosity", Schema::number().range(1e-3, 1.0).default_value("0.05"),
                "Floor of the porosity n = 1 - solid_fraction received.")
      .optional("drag_viscosity", Schema::number().non_negative().unit("Pa s").default_value("0"),
                "With drag: ice, the fluid viscosity the received drag_coefficient was computed "
                "for (the job's momentum_exchange.drag.fluid_viscosity): each fluid's share of the "
                "drag is then scaled by its own viscosity over this one, Darcy's drag being "
                "linear in the viscosity (air in the pores of a dry soil is dragged some 55 times "
                "less than water); every material then needs a viscosity. 0: every fluid takes "
                "the coefficient as received.")
      .optional("heat_exchange", Schema::boolean().default_value("false"),
                "Take part in the coupler's energy exchange: write fluid_temperature and "
                "fluid_heat_capacity, read heat_exchange_energy (Tran et al., MPMICE, eq. 23).");
  return coupling;
}

}  // namespace

Schema ice_case_schema() {
  Schema grid = Schema::object("The uniform grid.");
  grid.required("origin", vector_schema("m"), "Lower corner.")
      .required("upper", vector_schema("m"), "Upper corner.")
      .required("cells", Schema::vector(1, 3), "Cells per direction.");
  Schema file = Schema::file(
      "ice_case", "A multi-material compressible flow for ice_fluid (Tran et al., MPMICE's ICE).");
  file.required("name", Schema::string().non_empty(), "Name of the case.")
      .required("dimension", Schema::integer().range(1, 3), "1, 2 or 3.")
      .required("grid", grid, "The cells.")
      .optional("gravity", vector_schema("m/s^2").default_note("zero"), "Gravity vector.")
      .required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .optional("window", Schema::number().non_negative().unit("s").default_value("0"),
                "Standalone coupling window: steps end on window ends, and with "
                "--cosim-repeat-windows every window runs twice (a check of save and restore). "
                "0: the whole run is one window. Coupled, the job's window applies.")
      .required("materials", Schema::map_of(material_schema()),
                "The fluid materials by name, in this order (at most 8).")
      .optional("exchange", Schema::sequence(exchange_schema()),
                "Exchange coefficients per pair; pairs not listed exchange nothing.")
      .required("initial", initial_schema(), "The initial state.")
      .optional("boundaries", boundaries_schema(), "Boundary conditions.")
      .optional("numerics", numerics_schema(), "Time stepping and schemes.")
      .optional("output", output_schema(), "Outputs.")
      .optional("threads", Schema::integer().non_negative().default_value("0"),
                "Threads; 0: the default.")
      .optional("coupling", coupling_schema(), "Coupling with a porous solid.")
      .optional("limits", cosim::run_limits_schema(), "What the run may use.");
  return file;
}

std::string ice_case_help() {
  return ice_case_schema().help("ice_case (ice_fluid --config)") + "\n" +
         EosRegistry::instance().help();
}

}  // namespace ice

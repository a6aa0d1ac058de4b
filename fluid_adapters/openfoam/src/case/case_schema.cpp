#include "openfoam/case/case_schema.hpp"

#include "cosim/io/run_size.hpp"

namespace openfoam {

using cosim::config::Schema;

namespace {

Schema vector_schema(const char* unit) {
  return Schema::vector(2, 3).unit(unit);
}

Schema fluid_schema(const char* which) {
  Schema fluid = Schema::object(which);
  fluid.required("density", Schema::number().positive().unit("kg/m^3"), "Density.")
      .required("viscosity", Schema::number().positive().unit("Pa s"),
                "Dynamic viscosity (OpenFOAM's nu = viscosity / density).");
  return fluid;
}

Schema generate_schema() {
  Schema grid = Schema::object("One block of uniform cells.");
  grid.required("origin", vector_schema("m"), "Lower corner.")
      .required("upper", vector_schema("m"), "Upper corner.")
      .required("cells", Schema::vector(2, 3), "Cells per direction.");
  Schema fluids = Schema::object("The two fluids of the VOF case.");
  fluids.required("water", fluid_schema("The liquid (alpha.water = 1)."), "Water.")
      .required("air", fluid_schema("The gas (alpha.water = 0)."), "Air.");
  Schema box = Schema::object("Axis-aligned box.");
  box.required("lower", vector_schema("m"), "Lower corner.")
      .required("upper", vector_schema("m"), "Upper corner.");
  Schema region = Schema::object("Cells whose centre lies in the box start full of water.");
  region.required("box", box, "The box.");
  Schema pressure_side = Schema::object("A side held at a fixed pressure.");
  pressure_side.required("pressure", Schema::number().unit("Pa"),
                         "p_rgh on the side (p - rho g.x); water flows in, anything out.");
  // A note, not a value: a 2D case may not name its z sides at all.
  Schema side = Schema::any_of({Schema::one_of({"wall", "slip", "atmosphere"}), pressure_side})
                    .default_note("wall");
  Schema boundaries = Schema::object(
      "What each side is: wall (no slip), slip (free slip), atmosphere (open, total pressure "
      "0, air flows in, anything flows out) or {pressure: p} (fixed p_rgh, water flows in); "
      "default wall. In 2D z_min and z_max are OpenFOAM's empty front and back.");
  for (const char* s : {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"})
    boundaries.optional(s, side, "This side.");
  Schema generate = Schema::object(
      "A complete OpenFOAM case made by the adapter: blockMesh, setFields, the dictionaries of "
      "the solver (VOF water and air, laminar).");
  generate.required("dimension", Schema::integer().range(2, 3), "2 or 3.")
      .required("grid", grid, "The cells; in 2D one cell of the smallest spacing thick along z.")
      .optional("gravity", vector_schema("m/s^2").default_note("zero"), "Gravity vector.")
      .required("fluids", fluids, "Water and air.")
      .optional("surface_tension",
                Schema::number().non_negative().unit("N/m").default_value("0.07"),
                "Surface tension of the water-air interface.")
      .optional("water", Schema::sequence(region), "Regions that start full of water.")
      .optional("initial_pressure", Schema::number().unit("Pa").default_value("0"),
                "p_rgh inside at the start.")
      .optional("boundaries", boundaries, "The sides.");
  return generate;
}

}  // namespace

Schema openfoam_case_schema() {
  Schema gauge = Schema::object("A point whose cell is recorded at every window's end.");
  gauge.required("name", Schema::string().non_empty(), "Column prefix in gauges.csv.")
      .required("point", vector_schema("m"), "The point; its cell is the nearest centre.");
  Schema wave_gauge = Schema::object(
      "A generated case's column of cells whose water surface is recorded every window.");
  wave_gauge.required("name", Schema::string().non_empty(), "Column prefix in gauges.csv.")
      .required("x", Schema::number().unit("m"), "Where along x.")
      .optional("z", Schema::number().unit("m").default_value("0"), "Where along z (3D).");
  Schema output = Schema::object("What the run writes.").default_value("{}");
  output
      .optional("every", Schema::number().non_negative().unit("s").default_value("0"),
                "Snapshot interval (HDF5 + XDMF); 0: start and end only.")
      .optional("gauges", Schema::sequence(gauge),
                "Points recorded in gauges.csv (p, p_rgh, U, water fraction) every window.")
      .optional("wave_gauges", Schema::sequence(wave_gauge),
                "Water surface elevations recorded in gauges.csv every window (generated cases: "
                "the height of water in the cell column, from the grid's bottom).");
  Schema parallel = Schema::object(
      "Run OpenFOAM on several processes: the case is decomposed once at the start "
      "(decomposePar, method simple) and never reconstructed.");
  parallel
      .required("processes", Schema::integer().range(1, 1024),
                "How many MPI processes (a coupled job's `ranks: N` for this participant gives "
                "N without this block).")
      .optional("split", Schema::vector(2, 3).default_note("the fewest cut cell faces"),
                "Blocks per direction (x, y, z); their product is `processes`.");
  Schema soil = Schema::object("How the MPM soil enters OpenFOAM in a coupled run.");
  soil.optional("model", Schema::one_of({"parcels", "porosity_zones"}).default_value("parcels"),
                "parcels: MPPICInterFoam's cloud, one parcel per cell holding soil (moving, "
                "deforming soil); porosity_zones: interFoam's explicitPorositySource on zones "
                "rebuilt by topoSet each window (rigid, slow porous structures only: no porosity "
                "in continuity or inertia, no solid velocity in the drag).")
      .optional("zones", Schema::integer().range(1, 64).default_value("8"),
                "porosity_zones: at most this many zones, the cells' Darcy coefficients binned "
                "log-spaced (OpenFOAM takes one per zone).")
      .optional("parcel_density",
                Schema::number().positive().unit("kg/m^3").default_value("2.65e6"),
                "Parcel density: immense, so that the drag cannot move the parcels in a window "
                "(the drag itself does not depend on it).")
      .optional("max_solid_fraction", Schema::number().range(0.0, 1.0).default_value("0.99"),
                "OpenFOAM's alphaMax: the fluid fraction is clipped at 1 - this.")
      .optional("minimum_solid_fraction", Schema::number().range(0.0, 1.0).default_value("1e-6"),
                "Cells with less soil than this get no parcel.")
      .optional("displaced_water", Schema::boolean().default_value("true"),
                "Account for the water the moving soil displaces: MPPICInterFoam sees the "
                "soil's volume only between windows, so within a window its continuity lacks "
                "d(n)/dt = div(phi_s U_s); the parcels then move at U_s / n and the fluid "
                "velocity read back is shifted by -phi_s U_s / n, which solves the missing term "
                "exactly (false: the parcels move at U_s, and compaction-driven pore pressure "
                "is underestimated by the factor n).");
  Schema file = Schema::file(
      "openfoam_case",
      "A two-phase (water and air) flow run by Debian's stock OpenFOAM v1912 through case files "
      "(openfoam_adapter): OpenFOAM is restarted once per coupling window.");
  file.required("name", Schema::string().non_empty(), "Name of the case.")
      .optional("solver",
                Schema::one_of({"interFoam", "MPPICInterFoam"}).default_value("interFoam"),
                "The OpenFOAM application: interFoam (water and air), or MPPICInterFoam (water "
                "and air around the MPM soil as parcels; needed coupled with a soil).")
      .optional("soil", soil, "MPPICInterFoam: the soil's parcels.")
      .optional("parallel", parallel, "Parallel OpenFOAM (default: serial).")
      .optional("generate", generate_schema(),
                "Make the OpenFOAM case from these keys (give this or `directory`).")
      .optional("directory", Schema::path().must_exist(),
                "An existing OpenFOAM case (system/, constant/ and a 0/ directory), copied into "
                "the run directory and checked up front (give this or `generate`).")
      .required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .required("time_step", Schema::number().positive().unit("s"),
                "OpenFOAM's fixed deltaT; every window and snapshot interval is a whole number "
                "of steps.")
      .optional("window",
                Schema::number().positive().unit("s").default_note("output.every, else end_time"),
                "Standalone: OpenFOAM runs this long per start (the adapter reads its fields "
                "between starts). Coupled, the job's window applies.")
      .optional("window_timeout", Schema::number().positive().unit("s").default_value("600"),
                "Wall time one start of the solver may take; beyond it the solver is stopped "
                "and the run fails (exit 3) with its log's last lines.")
      .optional("keep_time_directories", Schema::boolean().default_value("false"),
                "Keep every window's OpenFOAM time directory (default: only the latest).")
      .optional("output", output, "Outputs.")
      .optional("limits", cosim::run_limits_schema(), "What the run may use.");
  return file;
}

std::string openfoam_case_help() {
  return openfoam_case_schema().help("openfoam_case (openfoam_adapter --config)");
}

}  // namespace openfoam

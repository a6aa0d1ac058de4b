#include "swe/case/case_schema.hpp"

#include <limits>

#include "cosim/io/run_size.hpp"
#include "swe/scheme.hpp"

namespace swe {

using cosim::config::Schema;

namespace {

constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

Schema mesh_schema() {
  Schema segment = Schema::object("A stretch of cells of about one width, up to `to`.");
  segment.required("to", Schema::number().unit("m"), "Upper end of the stretch.")
      .required("width", Schema::number().positive().unit("m"),
                "Target cell width; the stretch gets round(length / width) equal cells.");
  Schema mesh = Schema::object(
      "The cells. 1D: `from`, `to` and `cells` (uniform), or `from` and `segments` "
      "(non-uniform stretches), or `edges`. 2D: `origin`, `upper` and `cells` [nx, ny].");
  mesh.optional("from", Schema::number().unit("m"), "1D: lower end of the line.")
      .optional("to", Schema::number().unit("m"), "1D: upper end of the line (with `cells`).")
      .optional("cells", Schema::any(), "1D: number of uniform cells; 2D: [nx, ny].")
      .optional("segments", Schema::sequence(segment).length(1, unlimited),
                "1D: consecutive stretches of near-uniform cells from `from`.")
      .optional("edges", Schema::vector(2, unlimited).unit("m"), "1D: every cell edge, increasing.")
      .optional("origin", Schema::vector(2, 2).unit("m"), "2D: lower corner.")
      .optional("upper", Schema::vector(2, 2).unit("m"), "2D: upper corner.");
  return mesh;
}

Schema boundary_schema() {
  Schema values = Schema::object("A boundary with a value.");
  values
      .optional("inflow_discharge", Schema::number().unit("m^2/s"),
                "Discharge per unit width entering the domain; depth from the interior.")
      .optional("fixed_depth", Schema::number().positive().unit("m"),
                "Depth held at the face; velocity from the outgoing Riemann invariant.");
  return Schema::any_of({Schema::one_of({"wall", "transmissive"}), values});
}

Schema boundaries_schema() {
  Schema b = Schema::object(
      "Conditions per face: wall | transmissive | {inflow_discharge: q} | {fixed_depth: h}. "
      "1D faces: left, right; 2D: x_min, x_max, y_min, y_max. Default: wall.");
  for (const char* face : {"left", "right", "x_min", "x_max", "y_min", "y_max"})
    b.optional(face, boundary_schema(), "Condition on this face.");
  return b;
}

Schema bed_schema() {
  Schema bump = Schema::object("height cos^2(pi r / (2 radius)) within radius of centre.");
  bump.required("centre", Schema::vector(1, 2).unit("m"), "Centre (x or x, y).")
      .required("radius", Schema::number().positive().unit("m"), "Radius of the bump.")
      .required("height", Schema::number().unit("m"), "Height at the centre.");
  Schema bed = Schema::object(
                   "Initial bed elevation B = base + profile(x) + bumps. A coupled run "
                   "replaces it by the bed it receives.")
                   .default_value("{}");
  bed.optional("base", Schema::number().unit("m").default_value("0"), "Constant elevation.")
      .optional("profile", Schema::sequence(Schema::vector(2, 2)).length(2, unlimited),
                "Points [x, B] with increasing x, joined linearly; must cover the domain in x.")
      .optional("bumps", Schema::sequence(bump), "Bumps added to the bed.");
  return bed;
}

Schema region_schema() {
  Schema box = Schema::object("Axis-aligned box.");
  box.required("min", Schema::vector(1, 2).unit("m"), "Lower corner.")
      .required("max", Schema::vector(1, 2).unit("m"), "Upper corner.");
  Schema circle = Schema::object("Disc (2D).");
  circle.required("centre", Schema::vector(2, 2).unit("m"), "Centre.")
      .required("radius", Schema::number().positive().unit("m"), "Radius.");
  Schema region = Schema::object("Water set inside a shape; give `free_surface` or `depth`.");
  region.optional("box", box, "The region is a box.")
      .optional("circle", circle, "The region is a disc.")
      .optional("free_surface", Schema::number().unit("m"),
                "Free-surface elevation eta; h = max(0, eta - B).")
      .optional("depth", Schema::number().non_negative().unit("m"), "Depth h.")
      .optional("velocity", Schema::vector(1, 2).unit("m/s").default_note("zero"),
                "Depth-averaged velocity.");
  return region;
}

Schema initial_schema() {
  Schema initial = Schema::object(
      "Initial water: everywhere, then regions in order. Give `free_surface` or `depth`.");
  initial
      .optional("free_surface", Schema::number().unit("m"),
                "Free-surface elevation eta; h = max(0, eta - B).")
      .optional("depth", Schema::number().non_negative().unit("m"), "Depth h.")
      .optional("velocity", Schema::vector(1, 2).unit("m/s").default_note("zero"),
                "Depth-averaged velocity.")
      .optional("regions", Schema::sequence(region_schema()),
                "Regions overriding the water inside them.");
  return initial;
}

Schema gauge_schema() {
  Schema gauge = Schema::object("A free-surface gauge: give `x` (1D) or `position` (2D).");
  gauge.required("name", Schema::string().non_empty(), "Column name in gauges.csv.")
      .optional("x", Schema::number().unit("m"), "Position (1D).")
      .optional("position", Schema::vector(2, 2).unit("m"), "Position (2D).");
  return gauge;
}

Schema coupling_schema() {
  Schema coupling = Schema::object(
                        "Exchange with a soil solver on the mesh `swe_cells` (used only when run "
                        "by `cosim run`).")
                        .default_value("{}");
  coupling
      .optional(
          "reads",
          Schema::sequence(Schema::one_of({"bed_elevation", "solid_layer"}))
              .default_value("[bed_elevation]"),
          "bed_elevation [m] per cell: replaces the bed every step, keeping depths. solid_layer "
          "(2D, with `two_phase`): the columns of a depth-averaged mass per cell each window "
          "(column_volume, column_mass, column_momentum, structured_mass, released_fluid_volume): "
          "the fluid flows over bed + their depth, drags them and takes their released fluid.")
      .optional("writes",
                Schema::sequence(Schema::one_of({"bed_traction", "momentum_exchange_impulse",
                                                 "free_surface_elevation"}))
                    .default_value("[bed_traction]"),
                "bed_traction [Pa] per cell: horizontal component(s), then vertical. "
                "momentum_exchange_impulse [kg m/s] (with solid_layer): the drag's impulse on "
                "the solids of each cell. free_surface_elevation [m]: the water's surface, over "
                "dry cells the level of the nearest water.")
      .optional(
          "bed_pressure", Schema::one_of({"hydrostatic", "excess"}).default_value("hydrostatic"),
          "hydrostatic: p = rho g h normal to the bed (the soil then feels its buoyancy); "
          "excess: the waves' push p = rho g max(0, eta - eta_0) on wet cells, eta_0 the initial "
          "free surface above each cell, vertical only (Zheng et al., eq. 10 as used in their "
          "Secs. 4.3-4.4, where the soil's weight is total and never carried the water).");
  return coupling;
}

Schema two_phase_schema() {
  Schema drag = Schema::object(
                    "Pudasaini's generalised drag between the solids (with the fluid they confine) "
                    "and the free fluid, split between structured blocks and unconfined grains "
                    "(van den Bout et al., OpenLISEM Hazard, eqs. 61-64). Values out of range are "
                    "refused at their line.")
                    .default_value("{}");
  drag.optional("exponent_j", Schema::number().default_value("2"),
                "j in [1, 2] of the force C (u_u - u_c)|u_u - u_c|^(j-1): j = 1 is linear, "
                "j = 2 quadratic. (The paper's text calls quadratic j = 1; we follow its "
                "formula and settings.)")
      .optional("reynolds_exponent_M", Schema::number().default_value("2.4"),
                "M in [1, 10] of G = alpha_u^(M - 1); 2.4 to 4.65 (Pitman & Le 2005).")
      .optional("partition_exponent_m", Schema::number().default_value("1"),
                "m >= 0 of the partition factor P = ((1 - f_sc) alpha_s / ((1 - f_fc) "
                "alpha_f))^m.")
      .optional("grain_size", Schema::number().unit("m").default_value("1e-3"),
                "d > 0 of the unconfined grains (their settling velocity and Re_p).")
      .optional("block_size", Schema::number().unit("m").default_value("1"),
                "Mean size > 0 of the structured blocks.")
      .optional("smoothing_speed",
                Schema::number().unit("m/s").default_note("|alpha_c u_c + "
                                                          "alpha_u u_u|, eq. 63"),
                "K >= 0 of the smoothing S_p (eqs. 62-63); constant when given.");
  Schema box = Schema::object("Axis-aligned box.");
  box.required("min", Schema::vector(2, 2).unit("m"), "Lower corner.")
      .required("max", Schema::vector(2, 2).unit("m"), "Upper corner.");
  Schema layer = Schema::object(
      "A static solid layer laid at the start (standalone runs): uniform over `box`, or "
      "everywhere. The fluid's bed becomes bed + depth and the initial water is laid over it.");
  layer.required("depth", Schema::number().non_negative().unit("m"), "Solid depth h_s.")
      .required("density", Schema::number().positive().unit("kg/m^3"),
                "Bulk density rho_c of the solids with their confined fluid; in (rho_f, "
                "solid_density].")
      .optional("structured_share", Schema::number().range(0.0, 1.0).default_value("0"),
                "Share f_sc of the solids bound in structured blocks.")
      .optional("velocity", Schema::vector(2, 2).unit("m/s").default_note("zero"),
                "Solid velocity [u_s, v_s].")
      .optional("box", box, "Where the layer lies; everywhere when absent.");
  Schema two_phase = Schema::object(
      "Two-phase mode (2D only; van den Bout et al., OpenLISEM Hazard, eqs. 47-65): the free "
      "fluid flows over a solid layer (bed + h_s) and, after each fluid step, exchanges momentum "
      "with it by drag and virtual mass, exactly in time with the coefficients frozen over the "
      "step. Absent: single-phase shallow water.");
  two_phase.optional("drag", drag, "The drag law's parameters.")
      .optional("solid_density", Schema::number().positive().unit("kg/m^3").default_value("2650"),
                "Density rho_s of the grains; above the fluid's.")
      .optional("fluid_viscosity", Schema::number().positive().unit("Pa s").default_value("1e-3"),
                "Dynamic viscosity eta_f of the fluid.")
      .optional("virtual_mass", Schema::boolean().default_value("true"),
                "Include the virtual mass V = alpha_c rho_f C_vm, C_vm = (1 + 2 alpha_c) / (2 "
                "alpha_u) (eq. 65).")
      .optional("rain_rate", Schema::number().non_negative().unit("m/s").default_value("0"),
                "Uniform rain R added to every cell (without horizontal momentum).")
      .optional("infiltration_rate", Schema::number().non_negative().unit("m/s").default_value("0"),
                "Uniform infiltration I; a cell never loses more water than it holds.")
      .optional("solid_layer", layer, "A static initial solid layer.");
  return two_phase;
}

}  // namespace

Schema swe_case_schema() {
  Schema physics = Schema::object("Physical constants.").default_value("{}");
  physics.optional("gravity", Schema::number().positive().unit("m/s^2").default_value("9.81"), "g.")
      .optional("density", Schema::number().positive().unit("kg/m^3").default_value("1000"),
                "Water density.")
      .optional("manning", Schema::number().non_negative().unit("s/m^(1/3)").default_value("0"),
                "Manning coefficient M_b (Zheng et al., eq. 8).")
      .optional("dry_depth", Schema::number().positive().unit("m").default_value("1e-6"),
                "Depth below which a cell is dry (no velocity, no momentum).");
  Schema scheme = Schema::object("Numerical scheme.").default_value("{}");
  scheme
      .optional("flux", Schema::one_of(flux_names()).default_value("hllc"),
                "Face flux: roe (Zheng et al., eqs. 30-32), hll or hllc.")
      .optional("limiter", Schema::one_of(limiter_names()).default_value("van_leer"),
                "MUSCL slope limiter; none gives first order.")
      .optional("courant", Schema::number().range(1e-3, 1.0).default_value("0.5"),
                "Courant number C_r (Zheng et al., eq. 37); <= 0.5 keeps depths non-negative.");
  Schema time = Schema::object("Time stepping.");
  time.required("end_time", Schema::number().positive().unit("s"),
                "Simulated end time (standalone).")
      .optional("min_time_step", Schema::number().positive().unit("s").default_value("1e-9"),
                "A stable step below this ends the run as a numerical failure (exit 4).")
      .optional("max_time_step", Schema::number().non_negative().unit("s").default_value("0"),
                "Upper bound of the step; 0: none beyond stability.")
      .optional("window", Schema::number().non_negative().unit("s").default_value("0"),
                "Standalone coupling window: steps end on window ends, and with "
                "--cosim-repeat-windows every window runs twice (a check of save and restore). "
                "0: the whole run is one window. Coupled, the job's window applies.");
  Schema output = Schema::object("What the run writes.").default_value("{}");
  output
      .optional("every", Schema::number().non_negative().unit("s").default_value("0"),
                "Snapshot interval; 0: start and end only.")
      .optional("snapshots", Schema::boolean().default_value("true"),
                "HDF5 + XDMF snapshots of the cells.")
      .optional("gauge_every", Schema::number().non_negative().unit("s").default_value("0"),
                "Gauge interval; 0: every step.")
      .optional("gauges", Schema::sequence(gauge_schema()), "Free-surface gauges (gauges.csv).");

  Schema file = Schema::file(
      "swe_case", "A shallow-water case for swe_fluid (1D non-uniform or 2D uniform cells).");
  file.required("name", Schema::string().non_empty(), "Name of the case.")
      .required("dimension", Schema::integer().range(1, 2), "1 (line) or 2 (plan view).")
      .required("mesh", mesh_schema(), "The cells.")
      .optional("physics", physics, "Physical constants.")
      .optional("scheme", scheme, "Numerical scheme.")
      .optional("bed", bed_schema(), "Initial bed elevation.")
      .required("initial", initial_schema(), "Initial water.")
      .optional("boundaries", boundaries_schema(), "Boundary conditions.")
      .required("time", time, "Time stepping.")
      .optional("output", output, "Outputs.")
      .optional("threads", Schema::integer().non_negative().default_value("0"),
                "OpenMP threads; 0: OpenMP's default.")
      .optional("coupling", coupling_schema(), "Exchange with a soil solver.")
      .optional("two_phase", two_phase_schema(), "Free fluid over a solid layer (2D).")
      .optional("limits", cosim::run_limits_schema(), "What the run may use.");
  return file;
}

std::string swe_case_help() {
  return swe_case_schema().help("swe_case (swe_fluid --config)");
}

}  // namespace swe

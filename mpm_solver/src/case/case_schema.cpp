#include "mpm/case/case_schema.hpp"

#include <limits>

#include "cosim/io/run_size.hpp"
#include "mpm/coupling/coupling_spec.hpp"
#include "mpm/material/material_parameters.hpp"
#include "mpm/material/material_registry.hpp"

namespace mpm {

using cosim::config::Schema;

namespace {

constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

Schema coordinates() {
  return Schema::vector(2, 3);
}

Schema grid_schema() {
  Schema grid = Schema::object("The uniform background grid.");
  grid.required("origin", coordinates().unit("m"), "Lower corner, one value per dimension.")
      .optional("upper", coordinates().unit("m"), "Upper corner; give either `upper` or `spacing`.")
      .optional("spacing", coordinates().unit("m"), "Cell size per direction.")
      .required("cells", Schema::vector(2, 3), "Cells per direction (whole numbers >= 1).");
  return grid;
}

Schema time_schema() {
  Schema time = Schema::object("Time stepping.");
  time.required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .optional("safety_factor", Schema::number().range(1e-6, 1.0).default_value("0.5"),
                "alpha of the critical time step alpha h / (c + |v|) (Zheng et al., eq. 23).")
      .optional("min_time_step", Schema::number().positive().unit("s").default_value("1e-12"),
                "A stable time step below this ends the run as a numerical failure (exit 4).")
      .optional("max_time_step", Schema::number().positive().unit("s").default_note("none"),
                "Upper bound of the time step.")
      .optional("window", Schema::number().positive().unit("s").default_note("none"),
                "Standalone: run in coupling windows of this length through the participant "
                "API, each ending on a step (--cosim-repeat-windows runs every window twice, "
                "going back to its start once). Coupled, the job's window applies.");
  return time;
}

Schema rigid_schema() {
  Schema rigid = Schema::object("The body is rigid; its particles move together.");
  rigid
      .required("motion", Schema::one_of({"fixed", "prescribed", "free"}),
                "fixed: at rest; prescribed: velocity from `velocity_history`; free: translates "
                "under gravity and contact forces.")
      .optional("velocity_history", Schema::path().must_exist(),
                "CSV with header `time [s],vx [m/s],vy [m/s][,vz [m/s]]`, times increasing; "
                "linear between rows, constant beyond (motion: prescribed).");
  return rigid;
}

Schema geometry_schema() {
  Schema box = Schema::object("Axis-aligned box.");
  box.required("min", coordinates().unit("m"), "Lower corner.")
      .required("max", coordinates().unit("m"), "Upper corner.");
  Schema polyhedron = Schema::object("Closed triangulated surface (3D).");
  polyhedron
      .required("vertices", Schema::sequence(Schema::vector(3, 3)).length(4, unlimited),
                "Vertex coordinates [m].")
      .required("triangles", Schema::sequence(Schema::vector(3, 3)).length(4, unlimited),
                "Vertex indices (0-based) of each triangle, outward normals by the right-hand "
                "rule.");
  Schema geometry = Schema::object("Where the body's particles are seeded; exactly one key.");
  geometry.optional("box", box, "Axis-aligned box.")
      .optional("polygon", Schema::sequence(Schema::vector(2, 2)).length(3, unlimited),
                "Simple polygon (2D): vertices [x, y] in order [m].")
      .optional("polyhedron", polyhedron, "Closed triangulated surface (3D).")
      .optional("points", Schema::path().must_exist(),
                "CSV file of particle positions (and volumes), see the geometry module.");
  return geometry;
}

Schema porous_schema() {
  Schema permeability = Schema::object("Intrinsic permeability of the solid skeleton.");
  permeability
      .optional("model",
                Schema::one_of({"kozeny_carman_pan", "kozeny_carman_tran", "constant"})
                    .default_value("kozeny_carman_pan"),
                "kozeny_carman_pan: D50^2 n^3 / (150 (1 - n)^2) (Pan et al. 2021, eq. 76); "
                "kozeny_carman_tran: d^2 (1 - phi_s)^3 / (180 phi_s^2) (Tran et al., MPMICE, "
                "eq. 32); constant: `value`.")
      .optional("value", Schema::number().positive().unit("m^2"), "For model: constant.");
  Schema porous = Schema::object(
      "Porous skeleton: the material density is the grain density, particle mass rho_s (1 - n0) "
      "V.");
  porous.required("porosity", Schema::number().range(0.0, 0.99), "Initial porosity n0.")
      .optional("grain_size", Schema::number().positive().unit("m"),
                "D50 (needed by Kozeny-Carman).")
      .optional("max_porosity", Schema::number().range(0.0, 1.0).default_value("0.99"),
                "Cap of the porosity update (Pan et al. 2021, text after eq. 76).")
      .optional("permeability", permeability, "Permeability model.");
  return porous;
}

Schema geostatic_schema() {
  Schema geostatic = Schema::object(
      "Initial effective stress sigma'_v = -gamma' (surface - z), sigma'_h = K0 sigma'_v.");
  geostatic
      .optional("k0", Schema::number().non_negative().default_note("1 - sin(phi), or nu/(1 - nu)"),
                "Lateral earth pressure coefficient.")
      .optional("unit_weight", Schema::number().positive().unit("N/m^3").default_note("rho |g|"),
                "Effective unit weight gamma'.")
      .optional("surface", Schema::number().unit("m").default_note("top of the body"),
                "Elevation of the free surface.");
  return geostatic;
}

Schema body_schema() {
  Schema body = Schema::object("A body: deformable (`material`) or `rigid`.");
  body.required("name", Schema::string().non_empty(), "Unique name (contact pairs, loads, probes).")
      .optional("material", Schema::string().non_empty(), "Key of `materials` (deformable body).")
      .optional("rigid", rigid_schema(), "Rigid body instead of a material.")
      .optional("density", Schema::number().positive().unit("kg/m^3"),
                "Density of a rigid body (mass for contact and free motion).")
      .optional("temperature", Schema::number().positive().unit("K").default_value("293.15"),
                "Initial temperature.")
      .required("geometry", geometry_schema(), "Region the particles fill.")
      .optional(
          "particles_per_cell",
          Schema::any_of({Schema::integer().positive(), Schema::vector(2, 3)}).default_value("2"),
          "Particles per cell and direction (n gives n^dim per cell), or one count per "
          "direction; with r2 seeding the product is the number per cell volume.")
      .optional("seeding", Schema::one_of({"regular", "r2"}).default_value("regular"),
                "regular: cell-aligned lattice; r2: R2 quasi-random sequence.")
      .optional("initial_velocity", coordinates().unit("m/s").default_note("0"),
                "Velocity at t = 0.")
      .optional("porous", porous_schema(),
                "Porous medium (coupled with a fluid); a rigid body's pores keep their porosity.")
      .optional("geostatic", geostatic_schema(), "Geostatic initial stress.");
  material_parameters::add_thermal_keys(body,
                                        "Rigid body (a deformable body's are its material's). ");
  return body;
}

Schema contact_schema() {
  Schema pair = Schema::object("Friction of one pair of bodies.");
  pair.required("bodies", Schema::sequence(Schema::string()).length(2, 2), "Two body names.")
      .required("friction", Schema::number().non_negative(), "Coulomb coefficient.");
  Schema contact =
      Schema::object("Grid contact between bodies (one velocity field per body, Bardenhagen).");
  contact
      .optional("enabled", Schema::boolean().default_value("false"),
                "false: all bodies share one velocity field (no-slip).")
      .optional("friction", Schema::number().non_negative().default_value("0"),
                "Coulomb coefficient of every pair.")
      .optional("pairs", Schema::sequence(pair), "Per-pair coefficients.");
  return contact;
}

// The grid faces, as keys of `boundaries` and `thermal`.
const char* const grid_faces[][2] = {
    {"x_min", "The face x = origin_x."},      {"x_max", "The face x = upper_x."},
    {"y_min", "The face y = origin_y."},      {"y_max", "The face y = upper_y."},
    {"z_min", "The face z = origin_z (3D)."}, {"z_max", "The face z = upper_z (3D)."}};

Schema face_schema() {
  Schema frictional = Schema::object("Coulomb friction on the face.");
  frictional.required("frictional", Schema::number().non_negative(), "Coefficient mu.");
  return Schema::any_of({Schema::one_of({"free", "fixed", "slip"}), frictional})
      .default_note("free");
}

Schema boundaries_schema() {
  Schema boundaries = Schema::object(
      "Conditions on the grid values on each face: free | fixed (no motion) | slip (no normal "
      "motion) | {frictional: mu}.");
  for (const auto& [face, doc] : grid_faces) boundaries.optional(face, face_schema(), doc);
  return boundaries;
}

Schema thermal_schema() {
  Schema face = Schema::object("Temperature condition of the grid values on the face.");
  face.required("type", Schema::one_of({"insulated", "fixed_temperature"}),
                "insulated: no heat crosses the face; fixed_temperature: the grid values on it "
                "are held at `temperature`.")
      .optional("temperature", Schema::number().positive().unit("K"),
                "For type: fixed_temperature.");
  Schema thermal = Schema::object(
      "Heat conduction in the thermal bodies (Tran et al., MPMICE, eqs. 55-56, 92): one "
      "temperature field on the grid shared by every thermal body; the explicit step is also "
      "limited to safety_factor h^2 / (2 dim max k_eff / (rho c)).");
  thermal.optional("enabled", Schema::boolean().default_note("true when a body is thermal"),
                   "false: temperatures stay at their initial values.");
  for (const auto& [name, doc] : grid_faces)
    thermal.optional(name, Schema(face).default_note("{type: insulated}"), doc);
  return thermal;
}

Schema load_schema() {
  Schema region = Schema::object("Particles of the body inside this box carry the load.");
  region.required("min", coordinates().unit("m"), "Lower corner.")
      .required("max", coordinates().unit("m"), "Upper corner.");
  Schema load = Schema::object("A surface load on particles.");
  load.required("name", Schema::string().non_empty(), "Name.")
      .required("body", Schema::string().non_empty(), "Body the particles belong to.")
      .required("region", region, "Selects the loaded particles at t = 0.")
      .optional("face",
                Schema::one_of({"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"})
                    .default_value("y_max"),
                "Face of the particles' domains the load acts on.")
      .optional("traction", coordinates().unit("Pa"), "Traction vector.")
      .optional("pressure", Schema::number().unit("Pa"),
                "Pressure against the face's outward normal; give `traction` or `pressure`.")
      .optional("ramp_time", Schema::number().non_negative().unit("s").default_value("0"),
                "Ramp from zero over this time.")
      .optional("ramp_shape", Schema::one_of({"linear", "cycloidal"}).default_value("linear"),
                "linear: a constant rate; cycloidal: t/T - sin(2 pi t/T) / (2 pi), its rate zero "
                "at both ends (rings no elastic wave whose period divides the ramp time).");
  return load;
}

Schema probe_schema() {
  Schema probe = Schema::object("Records the particle nearest to `position` at t = 0.");
  probe.required("name", Schema::string().non_empty(), "Column prefix in probes.csv.")
      .required("body", Schema::string().non_empty(), "Body of the particle.")
      .required("position", coordinates().unit("m"), "A point inside the body.");
  return probe;
}

Schema output_schema() {
  Schema output = Schema::object("What the run writes.");
  output
      .optional("every", Schema::number().non_negative().unit("s").default_value("0"),
                "Particle snapshot interval; 0: first and last only.")
      .optional("grid", Schema::boolean().default_value("false"),
                "Also grid snapshots (nodal mass and velocity; linear and gimp shapes only).")
      .optional("probe_every", Schema::number().non_negative().unit("s").default_value("0"),
                "Probe interval; 0: at every snapshot.");
  return output;
}

}  // namespace

Schema mpm_case_schema() {
  Schema s = Schema::file("mpm_case", "A standalone case of the MPM solver.");
  s.optional("name", Schema::string().non_empty().default_note("file name"), "Case name.")
      .required("dimension", Schema::integer().range(2, 3), "2 (plane strain) or 3.")
      .required("grid", grid_schema(), "Background grid.")
      .optional("shape",
                Schema::one_of({"linear", "gimp", "quadratic_bspline"}).default_value("gimp"),
                "Shape functions.")
      .optional("scheme", Schema::one_of({"usl", "musl"}).default_value("musl"),
                "Update stress last, or modified USL (Pan et al. 2021).")
      .optional("flip_fraction", Schema::number().range(0.0, 1.0).default_value("0.99"),
                "1: pure FLIP, 0: pure PIC.")
      .optional("locking", Schema::one_of({"none", "bbar", "fbar"}).default_value("none"),
                "Volumetric locking mitigation.")
      .optional("gimp_domain", Schema::one_of({"initial", "deformed"}).default_value("initial"),
                "GIMP particle domain: the initial size (uGIMP), or stretched every step with the "
                "deformation gradient, l_i = l_0,i |F_ii| (cpGIMP). Read by the gimp shape only.")
      .required("time", time_schema(), "Time stepping.")
      .optional("gravity", coordinates().unit("m/s^2").default_note("0"),
                "Gravity vector, one value per dimension.")
      .optional("gravity_ramp_time", Schema::number().non_negative().unit("s").default_value("0"),
                "Gravity grows linearly from zero over this time.")
      .optional("damping", Schema::number().range(0.0, 1.0).default_value("0"),
                "Local non-viscous damping coefficient.")
      .optional("materials", Schema::map_of(Schema::any()),
                "Named materials, each a mapping with a `type` (models listed below); a case of "
                "rigid bodies only needs none.")
      .required("bodies", Schema::sequence(body_schema()).length(1, unlimited), "The bodies.")
      .optional("contact", contact_schema().default_value("{}"), "Contact between bodies.")
      .optional("boundaries", boundaries_schema(), "Grid faces.")
      .optional("thermal", thermal_schema(),
                "Heat conduction and the faces' temperature conditions.")
      .optional("loads", Schema::sequence(load_schema()), "Surface loads.")
      .optional("probes", Schema::sequence(probe_schema()), "Particles recorded to probes.csv.")
      .optional("output", output_schema().default_value("{}"), "Output.")
      .optional("coupling", coupling::coupling_schema(),
                "What the solver exchanges when `cosim run` starts it (ignored standalone).")
      .optional("threads", Schema::integer().non_negative().default_value("0"),
                "OpenMP threads; 0: the OpenMP default (--threads overrides).")
      .optional("limits", cosim::run_limits_schema(), "What the run may use.");
  return s;
}

std::string mpm_case_help() {
  return mpm_case_schema().help("MPM case file (kind: mpm_case)") + "\n" +
         MaterialRegistry::instance().help();
}

}  // namespace mpm

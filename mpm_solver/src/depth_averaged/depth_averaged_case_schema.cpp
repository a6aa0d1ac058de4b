#include <limits>

#include "cosim/io/run_size.hpp"
#include "mpm/depth_averaged/depth_averaged_case.hpp"
#include "mpm/material/cohesion_degradation.hpp"

namespace mpm {

using cosim::config::Schema;

namespace {

constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

Schema plane_point() {
  return Schema::vector(2, 2);
}

Schema grid_schema() {
  Schema grid = Schema::object(
      "The ground grid (quadratic B-splines) in the reference plane: x down its slope, y across.");
  grid.required("origin", plane_point().unit("m"), "Lower corner [x, y].")
      .optional("upper", plane_point().unit("m"), "Upper corner; give either `upper` or `spacing`.")
      .optional("spacing", plane_point().unit("m"), "Cell size per direction.")
      .required("cells", Schema::vector(2, 2), "Cells per direction (whole numbers >= 2).");
  return grid;
}

Schema terrain_schema() {
  Schema bed = Schema::object("The bed's elevation above the reference plane.");
  bed.required("raster", Schema::path().must_exist(),
               "ESRI ASCII grid (.asc) of the bed [m], read bilinearly between cell centres; it "
               "must cover the ground grid.");
  Schema terrain = Schema::object(
      "The ground: a reference plane inclined at `inclination`, and a bed above it (small slopes "
      "next to the plane's, Gray et al. 1999).");
  terrain
      .optional("inclination", Schema::number().range(0.0, 89.0).unit("deg").default_value("0"),
                "theta of the reference plane; 0: a catchment in plan view.")
      .optional("gravity", Schema::number().positive().unit("m/s^2").default_value("9.81"), "|g|.")
      .optional("bed", bed, "Bed raster; absent: the plane itself.");
  return terrain;
}

Schema material_schema() {
  Schema material = Schema::object(
      "A mass's material (van den Bout et al., OpenLISEM Hazard, eqs. 26, 36, 39, 42-43).");
  material
      .required("density", Schema::number().positive().unit("kg/m^3"),
                "Bulk density rho of the moving column (solids and the fluid they hold).")
      .required("internal_friction_angle", Schema::number().range(0.0, 89.0).unit("deg"),
                "phi: Rankine's K_a and K_p (eq. 42).")
      .required("basal_friction_angle", Schema::number().range(0.0, 89.0).unit("deg"),
                "delta: Coulomb friction on the bed, |S| = N tan(delta) (eq. 36).")
      .optional("cohesion", Schema::number().non_negative().unit("Pa").default_value("0"),
                "c: Bell's cohesion term of the lateral stress (eq. 43), with tension cracks.")
      .optional("structured_share", Schema::number().range(0.0, 1.0).default_value("1"),
                "f_sc at the start: the share of the solids bound in blocks; fragmentation turns "
                "them into loose grains (eq. 28).")
      .optional("basal_pressure_factor", Schema::number().range(0.0, 1.0).default_value("1"),
                "B of eq. 39: the share of a surrounding fluid's pressure that reaches the base "
                "through the blocks (loose grains always feel it all). The paper's settings use "
                "0, its discussion 1 for a saturated mass; we default to 1.")
      .optional(
          "fragmentation_strain",
          Schema::number().positive().default_note("the cohesion degradation's critical strain"),
          "epsilon_f of eq. 28: the dilation over which the blocks break up.")
      .optional("youngs_modulus", Schema::number().non_negative().unit("Pa").default_value("0"),
                "E of the in-plane stress (eq. 43's last term, eqs. 22-23 in the plane): elastic, "
                "bounded by Mohr-Coulomb with the cohesion left and internal_friction_angle, it "
                "holds a block together while its parts are driven apart, and a weak one tears. "
                "0: none, the earth pressure alone (the time step then ignores elastic waves).")
      .optional("poisson_ratio", Schema::number().range(0.0, 0.49).default_value("0.3"),
                "nu of the in-plane stress.")
      .optional("confined_fluid_fraction", Schema::number().range(0.0, 0.99).default_value("0"),
                "The share of a column's volume that is fluid confined in its blocks (f_fc "
                "alpha_f / alpha_c, eqs. 1-3): released as the blocks break up (eqs. 27, 28), it "
                "leaves the column with its mass and, coupled, becomes free water of swe_fluid.");
  CohesionDegradation::add_keys(material);
  return material;
}

Schema mass_schema() {
  Schema box = Schema::object("An axis-aligned rectangle in the plane.");
  box.required("min", plane_point().unit("m"), "Lower corner.")
      .required("max", plane_point().unit("m"), "Upper corner.");
  Schema region = Schema::object("Where the mass lies; exactly one key.");
  region.optional("box", box, "A rectangle.")
      .optional("polygon", Schema::sequence(plane_point()).length(3, unlimited),
                "A simple polygon: vertices [x, y] in order [m].");
  Schema depth_raster = Schema::object("Depth from a raster.");
  depth_raster.required("raster", Schema::path().must_exist(),
                        "ESRI ASCII grid of the mass's depth [m] (normal to the plane); it must "
                        "cover the region. Cells of depth 0 hold no mass.");
  Schema mass = Schema::object("A mass of one material, seeded as columns at rest or moving.");
  mass.required("name", Schema::string().non_empty(), "Unique name.")
      .required("material", Schema::string().non_empty(), "Key of `materials`.")
      .required("region", region, "Where it lies.")
      .required("depth", Schema::any_of({Schema::number().non_negative(), depth_raster}),
                "Its depth [m]: one value over the region, or {raster: file.asc}.")
      .optional("points_per_cell", Schema::integer().range(2, 4).default_value("2"),
                "Gauss-Legendre points per grid cell and direction.")
      .optional("initial_velocity", plane_point().unit("m/s").default_note("[0, 0]"),
                "Depth-averaged velocity at t = 0.");
  return mass;
}

Schema walls_schema() {
  Schema walls = Schema::object(
      "What the grid's faces do to the mass: slip (no normal motion) or stick (no motion).");
  for (const char* face : {"x_min", "x_max", "y_min", "y_max"})
    walls.optional(face, Schema::one_of({"slip", "stick"}).default_value("slip"), "The face.");
  return walls;
}

Schema numerics_schema() {
  Schema numerics = Schema::object("The scheme.");
  numerics
      .optional("courant", Schema::number().range(1e-3, 1.0).default_value("0.4"),
                "dt = courant dx / max(|u| + sqrt(K g cos(theta) h)).")
      .optional("flip_fraction", Schema::number().range(0.0, 1.0).default_value("0.99"),
                "Share of FLIP in the points' velocity update (the rest PIC).")
      .optional("split_length", Schema::number().non_negative().default_value("1"),
                "A point stretched past this many grid cells is split in two; 0: never.")
      .optional("earth_pressure", Schema::one_of({"isotropic", "rankine"}).default_value("rankine"),
                "K = 1 (isotropic, Mangeney et al.'s exact dam break), or Rankine's K_a where a "
                "column spreads and K_p where it converges (eq. 42).");
  return numerics;
}

Schema still_water_schema() {
  Schema water = Schema::object("A lake at rest around the mass (buoyancy and basal pressure).");
  water
      .required("level", Schema::number().unit("m"),
                "World elevation of its surface; the reference plane is at elevation 0 at x = 0 "
                "and falls along x at tan(inclination).")
      .optional("density", Schema::number().positive().unit("kg/m^3").default_note("fluid.density"),
                "rho_f; given, it is also the density of the fluid the columns confine.");
  return water;
}

Schema gauge_schema() {
  Schema gauge = Schema::object("A point where gauges.csv records the depth and the speed.");
  gauge.required("name", Schema::string().non_empty(), "Column prefix.")
      .required("position", plane_point().unit("m"), "[x, y] in the plane.");
  return gauge;
}

Schema output_schema() {
  Schema output = Schema::object("What the run writes.");
  output
      .optional("every", Schema::number().non_negative().unit("s").default_value("0"),
                "Snapshot interval (points and ground); 0: first and last only.")
      .optional("gauge_every", Schema::number().non_negative().unit("s").default_value("0"),
                "Gauge interval; 0: at every snapshot.");
  return output;
}

}  // namespace

Schema depth_averaged_case_schema() {
  Schema s = Schema::file(
      "depth_averaged_case",
      "A depth-averaged mass movement (van den Bout et al., OpenLISEM Hazard 2.0a): material "
      "points in the plane of the ground, each a column of the mass, run by mpm_solver.");
  s.optional("name", Schema::string().non_empty().default_note("file name"), "Case name.")
      .required("grid", grid_schema(), "The ground grid.")
      .optional("terrain", terrain_schema().default_value("{}"), "The ground.")
      .required(
          "time",
          Schema::object("Time stepping.")
              .required("end_time", Schema::number().positive().unit("s"), "Simulated end time."),
          "Time stepping.")
      .required("materials", Schema::map_of(material_schema()), "Named materials.")
      .required("masses", Schema::sequence(mass_schema()).length(1, unlimited), "The masses.")
      .optional("walls", walls_schema().default_value("{}"), "The grid's faces.")
      .optional("obstacles",
                Schema::sequence(Schema::object("A box standing on the ground: the grid's nodes "
                                                "inside it are held still (a stick wall).")
                                     .required("min", plane_point().unit("m"), "Lower corner.")
                                     .required("max", plane_point().unit("m"), "Upper corner.")),
                "Fixed obstacles the mass stops against and flows around.")
      .optional("numerics", numerics_schema().default_value("{}"), "The scheme.")
      .optional("still_water", still_water_schema(), "A lake around the mass; absent: none.")
      .optional(
          "fluid",
          Schema::object("The water around and inside the mass.")
              .optional("density", Schema::number().positive().unit("kg/m^3").default_value("1000"),
                        "rho_f: of the fluid the columns confine and release, of the "
                        "still water, and of a coupled swe_fluid's water (give its "
                        "physics.density).")
              .default_value("{}"),
          "The water's density.")
      .optional("gauges", Schema::sequence(gauge_schema()), "Points recorded to gauges.csv.")
      .optional("output", output_schema().default_value("{}"), "Output.")
      .optional("threads", Schema::integer().non_negative().default_value("0"),
                "OpenMP threads; 0: the OpenMP default (--threads overrides).")
      .optional("limits", cosim::run_limits_schema(), "What the run may use.");
  return s;
}

std::string depth_averaged_case_help() {
  return depth_averaged_case_schema().help("Depth-averaged case file (kind: depth_averaged_case)");
}

}  // namespace mpm

#include "bench/suite.hpp"

namespace cosim::bench {

using config::Schema;

namespace {

Schema overrides_schema() {
  return Schema::map_of(Schema::map_of(Schema::any())).default_value("{}");
}

const char* const overrides_doc =
    "Values put into the run's input files: {<role>: {<key.path>: value}}, role soil | fluid | "
    "case | job; the key path is dotted, sequence items by index (bodies.0.porous.porosity).";

Schema resolution_schema() {
  Schema s = Schema::object("What changes at one resolution only.");
  s.optional("set", overrides_schema(), overrides_doc);
  return s;
}

Schema backend_resolution_schema() {
  Schema s = resolution_schema();
  s.optional("case", Schema::path().must_exist(), "Another case file at this resolution.")
      .optional("fluid", Schema::path().must_exist(), "Another fluid case at this resolution.")
      .optional("job", Schema::path().must_exist(),
                "Another job at this resolution (e.g. a paper's grid in full/).");
  return s;
}

Schema level_schema() {
  Schema s = Schema::object("One grid of a refinement study.");
  s.required("label", Schema::string().non_empty(), "Its name in the report (e.g. '100 cells').")
      .required("cells", Schema::number().positive(),
                "Cells across the domain: the axis of the error-against-resolution plot.")
      .optional("set", overrides_schema(), overrides_doc)
      .optional("resolution", Schema::one_of({"coarse", "full"}),
                "Run this level at this --resolution only (default: at both).");
  return s;
}

Schema backend_schema() {
  Schema s =
      Schema::object("How one backend runs the scenario: exactly one of case, fluid and job.");
  s.optional("case", Schema::path().must_exist(),
             "A standalone case of the backend's solver (kind: ice_case, openfoam_case, "
             "swe_case or mpm_case), run as `<solver> --config`.")
      .optional("fluid", Schema::path().must_exist(),
                "The backend's fluid case, coupled to the scenario's soil by the backend's "
                "pairing (the job is built by the bench).")
      .optional("job", Schema::path().must_exist(), "A ready job (kind: job), run as it is.")
      .optional("set", overrides_schema(), overrides_doc)
      .optional("coarse", backend_resolution_schema(),
                "Overrides (or another file of the same form) at --resolution coarse.")
      .optional("full", backend_resolution_schema(),
                "Overrides (or another file of the same form) at --resolution full.")
      .optional("levels", Schema::sequence(level_schema()).length(1, 32),
                "Run the backend on several grids (error against resolution).");
  return s;
}

Schema coupling_schema() {
  Schema s = Schema::object("The job settings of a coupled scenario, shared by its pairings.");
  s.required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .required("window", Schema::number().positive().unit("s"), "Coupling window.")
      .optional("drag", Schema::any(),
                "The drag law (the job's momentum_exchange.drag): {law: kozeny_carman | "
                "forchheimer | beetstra | constant, ...}; the porous pairings (ice, openfoam) "
                "need it.")
      .optional("optional_reads", Schema::sequence(Schema::one_of({"solid_volume_flux"})),
                "Fields the soil also sends to backends that read them.");
  return s;
}

Schema offset_schema() {
  return Schema::any_of({Schema::number(), Schema::map_of(Schema::number())}).default_value("0");
}

const char* const offset_doc =
    "Subtracted from every value (e.g. the still-water level), or {<backend>: offset} where "
    "the backends' data differ (ICE's pressure is absolute, OpenFOAM's relative to the "
    "atmosphere).";

// Keys every quantity takes.
Schema& with_common_keys(Schema& s, bool participant) {
  s.optional("divide_by", Schema::number().default_value("1"),
             "Values are divided by it (e.g. h_s, or sqrt(g h_s) for a speed), after the offset.");
  if (participant)
    s.optional("participant", Schema::string().non_empty(),
               "Coupled runs: whose output (default: the fluid, `water`).");
  return s;
}

Schema gauge_schema() {
  Schema s = Schema::object("A gauge's recorded value (the backend's gauges.csv).");
  s.required("name", Schema::string().non_empty(), "The gauge's name in the case.")
      .required("variable",
                Schema::one_of({"pressure", "velocity_x", "velocity_y", "velocity_z",
                                "water_fraction", "surface_elevation", "depth", "speed"}),
                "What it recorded.")
      .optional("at", Schema::any().default_value("end"),
                "end | max | min | series | first_above (the time the value first exceeds "
                "`threshold`) | a time [s] (the nearest row).")
      .optional("threshold", Schema::number().default_value("0"),
                "at: first_above: the value to exceed (after the offset).")
      .optional("offset", offset_schema(), offset_doc);
  with_common_keys(s, true);
  return s;
}

Schema time_series_schema() {
  Schema s = Schema::object("A column of any CSV file of the run.");
  s.required("file", Schema::string().non_empty(),
             "The file, relative to the run's output (e.g. water/water.csv).")
      .required("column", Schema::string().non_empty(), "Its header, e.g. 'speed_max [m/s]'.")
      .optional("at", Schema::any().default_value("end"),
                "end | max | min | series | a time [s] (the nearest row).")
      .optional("offset", offset_schema(), offset_doc);
  with_common_keys(s, false);
  return s;
}

Schema profile_schema() {
  Schema s = Schema::object("A field along a straight line, from the snapshot nearest a time.");
  s.required("field",
             Schema::one_of({"pressure", "density", "velocity_x", "velocity_y", "water_fraction",
                             "depth", "free_surface", "temperature"}),
             "The field (each backend's own name for it is looked up; free_surface of a 2D "
             "fluid on cells is the domain's top minus the air in the column, sum a dy with a "
             "the air's share of each cell's fluid).")
      .required("from", Schema::vector(1, 3), "Start of the line [m].")
      .required("to", Schema::vector(1, 3), "End of the line [m].")
      .optional("points", Schema::integer().range(2, 100000).default_value("50"),
                "Sample points, ends included.")
      .optional("time", Schema::number().non_negative().unit("s"),
                "Snapshot time (default: the last snapshot).")
      .optional("time_tolerance", Schema::number().non_negative().unit("s"),
                "How far the snapshot may be from `time` (default 5 % of it).")
      .optional("axis", Schema::one_of({"x", "y", "z"}).default_value("x"),
                "The coordinate the curve is drawn against.")
      .optional("offset", offset_schema(), offset_doc);
  with_common_keys(s, true);
  return s;
}

Schema water_front_schema() {
  Schema s = Schema::object(
      "The water's front along the floor against time, from every snapshot: the downstream edge "
      "of the last bottom-row cell holding more water than `threshold`.");
  s.optional("threshold", Schema::number().range(0.0, 1.0).default_value("0.5"),
             "Water fraction (ICE, OpenFOAM) or depth [m] (shallow water) that counts as wet.")
      .optional("length_scale", Schema::number().positive().default_value("1"),
                "Positions are divided by it (e.g. the column width a).")
      .optional("time_scale", Schema::number().positive().default_value("1"),
                "Times are multiplied by it (e.g. sqrt(2 g / a)).")
      .optional("start", Schema::vector(2, 2),
                "A first point (time, position) before the first snapshot, e.g. [0, 1].");
  with_common_keys(s, true);
  return s;
}

Schema wall_gradient_schema() {
  Schema s = Schema::object(
      "The normal derivative of a field at a wall of a fluid's grid, along the axis, averaged "
      "over the wall (second order one-sided from the wall's value): e.g. a Nusselt number with "
      "divide_by = -dT / H.");
  s.required("field", Schema::one_of({"temperature", "pressure", "velocity_x", "velocity_y"}),
             "The field.")
      .required("wall", Schema::one_of({"x_min", "x_max", "y_min", "y_max"}), "The wall.")
      .required("wall_value", Schema::number(), "The field's value on the wall.")
      .optional("time", Schema::number().non_negative().unit("s"),
                "Snapshot time (default: the last).")
      .optional("time_tolerance", Schema::number().non_negative().unit("s"),
                "How far the snapshot may be from `time` (default 5 % of it).");
  with_common_keys(s, true);
  return s;
}

Schema soil_schema() {
  Schema s = Schema::object("The soil's extent from the MPM's particle snapshots.");
  s.required("measure",
             Schema::one_of({"front", "back", "height", "toe", "runout", "height_change",
                             "max_speed", "front_series", "height_series"}),
             "front / back: largest / smallest x of the moving bodies' points; height: largest "
             "y; toe: the furthest point within base_band of the lowest (Zheng et al.); runout: "
             "toe now minus toe at the start; height_change: height now over height at the "
             "start; max_speed: the fastest point; *_series: against time.")
      .optional("time_tolerance", Schema::number().non_negative().unit("s"),
                "How far the snapshot may be from `time` (default 5 % of it).")
      .optional("base_band", Schema::number().positive().unit("m").default_value("0.1"),
                "toe and runout: how far above the lowest point counts as the base.")
      .optional("divide_by", Schema::number().default_value("1"), "Values are divided by it.")
      .optional("time", Schema::number().non_negative().unit("s"),
                "Snapshot time (default: the last).")
      .optional("participant", Schema::string().non_empty().default_value("soil"),
                "The MPM participant's name in the job (coupled runs).");
  return s;
}

Schema summary_value_schema() {
  Schema s = Schema::object("A number in a summary.json of the run.");
  s.required("value", Schema::string().non_empty(),
             "JSON pointer, e.g. /metrics/max_conservative_mapping_error/value.")
      .optional("participant", Schema::string().non_empty(),
                "Whose summary (default: the run's top summary.json).");
  with_common_keys(s, false);
  return s;
}

Schema quantity_schema() {
  Schema s = Schema::object("What the metric measures in a finished run: exactly one kind.");
  s.optional("gauge", gauge_schema(), "A gauge of the fluid backend.")
      .optional("time_series", time_series_schema(), "A column of a CSV file of the run.")
      .optional("profile", profile_schema(), "A field along a line.")
      .optional("water_front", water_front_schema(), "The water's front against time.")
      .optional("soil", soil_schema(), "The soil's extent.")
      .optional("wall_gradient", wall_gradient_schema(), "A field's gradient at a wall.")
      .optional("summary", summary_value_schema(), "A number of a summary.json.");
  return s;
}

Schema reference_schema() {
  Schema s = Schema::object(
      "What the metric is compared with: exactly one of value, analytic and csv (absent: "
      "measured only).");
  s.optional("value", Schema::number(), "A number, in the metric's unit.")
      .optional("analytic", Schema::string().non_empty(),
                "A named solution (`cosim bench --help-config` lists them), with its "
                "`parameters`.")
      .optional("csv", Schema::path().must_exist(),
                "A CSV file of reference numbers; with `column` one number, with `x` and `y` a "
                "curve.")
      .optional("column", Schema::string().non_empty(), "csv: the column of one number.")
      .optional("x", Schema::string().non_empty(), "csv: the column of the curve's abscissa.")
      .optional("y", Schema::string().non_empty(), "csv: the column of the curve's values.")
      .optional("where", Schema::map_of(Schema::any()),
                "csv: only rows whose columns hold these values.")
      .optional("label", Schema::string(), "The reference's name in tables and plots.")
      .optional("parameters", Schema::map_of(Schema::number()),
                "analytic: the solution's parameters.");
  return s;
}

Schema error_schema() {
  const std::vector<std::string> norms{"relative",     "absolute", "max_abs",
                                       "mean_abs",     "rms",      "relative_l1",
                                       "max_relative", "speed",    "max_relative_offset_fitted"};
  Schema detailed = Schema::object("A norm with options.");
  detailed.required("norm", Schema::one_of(norms), "The error's measure.")
      .optional("scale", Schema::number().positive().default_value("1"),
                "The error is divided by it (e.g. the load p0).")
      .optional("window", Schema::vector(2, 2),
                "Only reference points with abscissa in [a, b] count.")
      .optional("offsets", Schema::vector(2, 2).default_value("[0, 0]"),
                "max_relative_offset_fitted: the range of abscissa shifts searched.");
  return Schema::any_of({Schema::one_of(norms), detailed});
}

Schema metric_schema() {
  Schema s = Schema::object("One number the report gives per backend.");
  s.required("name", Schema::string().non_empty(), "Identifier (results.csv, plot files).")
      .optional("label", Schema::string(), "What it is, in words.")
      .optional("unit", Schema::string().default_value("1"), "SI unit of the value.")
      .required("quantity", quantity_schema(), "What is measured.")
      .optional("reference", reference_schema(), "What it is compared with.")
      .optional("error", error_schema().default_value("relative"),
                "relative | absolute (scalars); max_abs | mean_abs | rms | relative_l1 (sum of "
                "|differences| over sum of |reference|) | max_relative | speed (of the slope "
                "between the window's ends) | max_relative_offset_fitted (curves).")
      .optional("tolerance",
                Schema::any_of({Schema::number().non_negative(),
                                Schema::map_of(Schema::number().non_negative())}),
                "Largest error that passes, or {<backend>: tolerance} (a backend left out, or "
                "no tolerance at all: measured only).")
      .optional("resolution", Schema::one_of({"coarse", "full"}),
                "Measure it at this --resolution only (e.g. a time the coarse run does not "
                "reach).")
      .optional("summarize", Schema::one_of({"end", "max", "min", "mean"}).default_value("end"),
                "The value given for a curve.");
  return s;
}

Schema scenario_schema() {
  Schema s = Schema::object("One physical set-up, run with each of its backends.");
  s.required("name", Schema::string().non_empty(), "Identifier (--only, run directories).")
      .optional("title", Schema::string(), "Heading in the report.")
      .optional("about", Schema::string(), "The physics and the reference, for the report.")
      .optional("soil", Schema::path().must_exist(),
                "Coupled scenarios: the soil's MPM case, shared by every pairing.")
      .optional("coupling", coupling_schema(), "Coupled scenarios: the job's settings.")
      .optional("set", overrides_schema(), "Overrides of the soil and job for every backend.")
      .optional("coarse", resolution_schema(), "Overrides at --resolution coarse.")
      .optional("full", resolution_schema(), "Overrides at --resolution full.")
      .required("backends", Schema::map_of(backend_schema()).length(1, 5),
                "ice | openfoam | swe | mpm | coupler -> how it runs the scenario.")
      .optional("not_represented", Schema::map_of(Schema::string().non_empty()),
                "Backends that cannot run the scenario -> why, in one line with the measured "
                "reason (shown in the report beside those that ran).")
      .optional("metrics", Schema::sequence(metric_schema()).default_value("[]"),
                "What the report measures.");
  return s;
}

Schema make_suite_schema() {
  Schema s = Schema::file("bench_suite",
                          "Scenarios run across solver pairings and compared with their "
                          "references (`cosim bench`).");
  s.required("name", Schema::string().non_empty(), "Identifier of the suite.")
      .optional("title", Schema::string(), "Title of the report.")
      .optional("about", Schema::string(), "Introduction of the report.")
      .required("scenarios", Schema::sequence(scenario_schema()).length(1, 256), "The scenarios.");
  return s;
}

}  // namespace

const config::Schema& suite_schema() {
  static const Schema schema = make_suite_schema();
  return schema;
}

}  // namespace cosim::bench

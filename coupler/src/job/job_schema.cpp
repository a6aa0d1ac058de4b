#include "exchange/drag_law_registry.hpp"
#include "job/job.hpp"

namespace cosim::job {

using config::Schema;

namespace {

Schema mesh_schema() {
  Schema s = Schema::object(
      "A mesh the participant declares, so the job can be checked before it "
      "starts.");
  s.required("kind",
             Schema::one_of({"uniform_grid", "nonuniform_line", "point_cloud", "cell_cloud"}),
             "Mesh kind (architecture.md §5).")
      .required("dim", Schema::integer().range(1, 3), "Spatial dimension.");
  return s;
}

Schema participant_schema() {
  Schema s = Schema::object("One solver process.");
  s.required("executable", Schema::string().non_empty(),
             "Program to start: a name found next to `cosim` (build/bin) or on PATH, or a path.")
      .optional("config", Schema::path().must_exist(),
                "The solver's own config file, passed as --config (relative to this file).")
      .optional("args", Schema::sequence(Schema::string()).default_value("[]"),
                "Extra command-line arguments.")
      .optional("ranks", Schema::integer().range(1, 100000).default_value("1"),
                "MPI ranks the participant's program runs on (its MPMD count under mpirun or "
                "srun); more than 1 needs `transport: mpi` and a program that runs decomposed. "
                "For openfoam_adapter, the processes OpenFOAM runs on (the adapter is one "
                "process, on either transport).")
      .optional("meshes", Schema::map_of(mesh_schema()).default_value("{}"),
                "Meshes the participant declares: name -> {kind, dim}.")
      .optional("writes", Schema::map_of(Schema::string().non_empty()).default_value("{}"),
                "Fields it writes: field name -> mesh name.")
      .optional("reads", Schema::map_of(Schema::string().non_empty()).default_value("{}"),
                "Fields it reads: field name -> mesh name.");
  return s;
}

Schema mapping_schema() {
  Schema detailed = Schema::object("Mapping with options.");
  detailed
      .required("constraint", Schema::one_of({"conservative", "consistent"}),
                "conservative (extensive fields: totals kept) or consistent (intensive "
                "fields: averages).")
      .optional("kernel", Schema::one_of({"linear", "quadratic_bspline"}).default_value("linear"),
                "Kernel between point/cell clouds and grids.")
      .optional("bounds", Schema::vector(2, 2),
                "[lo, hi]: keep the mapped fraction within bounds, redistributing any excess "
                "to neighbours so the total is kept.");
  return Schema::any_of({Schema::one_of({"conservative", "consistent"}), detailed});
}

Schema exchange_schema() {
  Schema s = Schema::object("One field sent from one participant to another.");
  s.required("field", Schema::string().non_empty(), "Field name (the same on both sides).")
      .required("from", Schema::string().non_empty(), "Participant that writes it.")
      .required("to", Schema::string().non_empty(), "Participant that reads it.")
      .required("mapping", mapping_schema(), "How values move between the two meshes.");
  return s;
}

Schema zmq_schema() {
  Schema s = Schema::object("ZeroMQ transport options.");
  s.optional("scheme", Schema::one_of({"ipc", "tcp"}).default_value("ipc"),
             "ipc: sockets in a private 0700 directory; tcp: a loopback port.")
      .optional("host", Schema::string().non_empty().default_value("127.0.0.1"),
                "tcp interface to bind.")
      .optional("allow_non_loopback", Schema::boolean().default_value("false"),
                "Allow binding a host other than loopback.");
  return s;
}

Schema stability_check_schema() {
  Schema s = Schema::object(
      "The explicit coupling's window against its stability bound (architecture.md §3): with a "
      "momentum exchange and a compressible fluid, the coupler computes from window 0 the time "
      "the pore fluid's undrained pressure wave takes across an exchange cell, warns when the "
      "window is longer, and refuses the run before its first window when it is much longer.");
  s.optional("refuse_above", Schema::number().range(1.0, 1e6).default_value("10"),
             "Refuse a window longer than this many times the bound.")
      .optional("accept_unstable", Schema::boolean().default_value("false"),
                "Run anyway, with the warning, however long the window.");
  return s;
}

Schema output_schema() {
  Schema s = Schema::object("What the coupler writes besides log.txt and summary.json.");
  s.optional("every", Schema::number().non_negative().unit("s").default_value("0"),
             "Interval of snapshots of the exchanged fields (0: none).");
  return s;
}

Schema momentum_exchange_schema() {
  Schema s = Schema::object("Implicit momentum exchange of a fluid and a porous solid.");
  s.required("fluid", Schema::string().non_empty(),
             "Participant writing fluid_velocity and fluid_bulk_density.")
      .required("solid", Schema::string().non_empty(),
                "Participant writing solid_fraction, solid_velocity and solid_bulk_density.")
      .required("mesh", Schema::string().non_empty(),
                "Exchange mesh, as <participant>.<mesh> (usually the fluid's grid).")
      .required("drag", Schema::any(),
                "Drag law: a mapping with `law: <name>` and that law's keys, each law listed "
                "below as `momentum_exchange.drag with law: <name>`.")
      .optional("solved_by", Schema::one_of({"coupler", "fluid"}).default_value("coupler"),
                "coupler: the exchange is solved once per window and both phases read "
                "momentum_exchange_impulse; fluid: the fluid solves it in each of its steps "
                "with the drag_coefficient the coupler sends, and writes the momentum the "
                "solid receives as momentum_exchange_impulse.");
  return Schema::any_of({Schema::one_of({"none"}), s});
}

Schema energy_exchange_schema() {
  Schema s = Schema::object(
      "Implicit energy exchange of a fluid and a solid sharing cells (Tran et al., MPMICE, eq. "
      "23).");
  s.required("fluid", Schema::string().non_empty(),
             "Participant writing fluid_temperature and fluid_heat_capacity.")
      .required("solid", Schema::string().non_empty(),
                "Participant writing solid_temperature and solid_heat_capacity.")
      .required("mesh", Schema::string().non_empty(),
                "Exchange mesh, as <participant>.<mesh> (usually the fluid's grid).")
      .required("coefficient", Schema::number().non_negative().unit("W/(m^3 K)"),
                "Heat exchange coefficient H per unit volume of the mixture.");
  return Schema::any_of({Schema::one_of({"none"}), s});
}

Schema convergence_measure_schema() {
  Schema s = Schema::object(
      "A convergence measure of one field the coupler sends, with r = H(x) - x its change over "
      "an iteration (2-norm over the field's values); the field has converged when any limit "
      "given holds, and a window when every field has.");
  s.required("field", Schema::string().non_empty(),
             "<participant>.<field>: a field the coupler sends that participant.")
      .optional("relative", Schema::number().positive(), "||r|| <= relative ||H(x)||.")
      .optional("absolute", Schema::number().positive(), "||r|| <= absolute, in the field's unit.")
      .optional("residual_relative", Schema::number().positive(),
                "||r|| <= residual_relative times ||r|| of the window's first iteration.");
  return s;
}

Schema acceleration_schema() {
  Schema s = Schema::object(
      "How the next iterate of an implicit window is made from the last one, x, and the "
      "participants' answer to it, H(x).");
  s.optional("method",
             Schema::one_of({"none", "constant", "aitken", "iqn-ils", "iqn-imvj"})
                 .default_value("iqn-ils"),
             "none: x = H(x); constant: under-relaxation by `relaxation`; aitken: dynamic "
             "relaxation (Kuettler & Wall 2008); iqn-ils: interface quasi-Newton with an inverse "
             "least-squares Jacobian (Degroote et al. 2009); iqn-imvj: the same with the "
             "Jacobian carried from window to window as low-rank updates (Lindner et al. "
             "2015).")
      .optional(
          "relaxation", Schema::number().range(1e-6, 1.0).default_value("0.5"),
          "constant: the factor; aitken: the first iteration's; iqn-ils, iqn-imvj: the factor "
          "of an iteration with no column (nor Jacobian) yet.")
      .optional("max_columns", Schema::integer().range(1, 10000).default_value("100"),
                "iqn-ils, iqn-imvj: most columns kept in the least-squares system.")
      .optional("reuse_windows", Schema::integer().range(0, 1000).default_value("8"),
                "iqn-ils: keep the columns of this many converged windows for the next; iqn-imvj: "
                "the Jacobian updates of this many.")
      .optional("filter", Schema::one_of({"none", "qr1", "qr2"}).default_value("qr2"),
                "iqn-ils, iqn-imvj: drop (nearly) dependent columns (Haelterman et al. 2016).")
      .optional("filter_limit", Schema::number().range(1e-16, 0.5).default_value("1e-2"),
                "iqn-ils, iqn-imvj: the filter's threshold.")
      .optional("preconditioner",
                Schema::one_of({"none", "value", "residual-sum", "convergence"})
                    .default_value("residual-sum"),
                "Scaling of each field's part of the quasi-Newton system, so fields in Pa and "
                "m/s converge together: value, residual-sum (preCICE's preconditioners), "
                "convergence (each field by the inverse of the residual its convergence measure "
                "accepts, every iteration).")
      .optional("freeze_preconditioner_after",
                Schema::integer().range(0, 1000000).default_value("0"),
                "Windows after which the scaling stops changing (0: never).")
      .optional("fields", Schema::sequence(Schema::string().non_empty()),
                "<participant>.<field> the accelerator updates; the others take H(x). Default: "
                "every field the coupler sends (serial schemes: sends `first`), but an "
                "exchange's answers (momentum_exchange_impulse solved by the coupler, "
                "heat_exchange_energy).");
  return s;
}

Schema coupling_schema() {
  Schema s = Schema::object(
      "The coupling scheme: one exchange per window (explicit), or windows repeated until the "
      "exchanged fields converge (implicit; architecture.md §13).");
  s.optional("scheme",
             Schema::one_of(
                 {"parallel-explicit", "parallel-implicit", "serial-explicit", "serial-implicit"})
                 .default_value("parallel-explicit"),
             "parallel-explicit: every participant runs a window at once on the fields of the "
             "window before; parallel-implicit: the same, repeated from the window's start until "
             "the `convergence` measures hold; serial-explicit: two participants, `first` runs "
             "the window, then the other on its new values; serial-implicit: the same, repeated "
             "until converged.")
      .optional("first", Schema::string().non_empty(),
                "Serial schemes: the participant that runs each window first (default: the first "
                "one listed).")
      .optional("time_interpolation",
                Schema::one_of({"constant", "linear"}).default_value("constant"),
                "Implicit and serial schemes: what a participant reads inside a window from "
                "window-end values it holds (an implicit scheme's iterate, or, serially, the "
                "first participant's new values read by the second): those values, or values "
                "linear in time between the window's accepted start and them (waveform "
                "relaxation).")
      .optional("max_iterations", Schema::integer().range(1, 100000).default_value("50"),
                "Implicit schemes: the most iterations of a window.")
      .optional("on_max_iterations", Schema::one_of({"continue", "stop"}).default_value("stop"),
                "continue: take the last iterate, warn, and count the window as not converged; "
                "stop: end the run with exit 4 naming the window, the field and its residual.")
      .optional("divergence_factor", Schema::number().range(1.0, 1e300).default_value("1e3"),
                "A residual that grows by more than this factor over one iteration, to more than "
                "a tenth of the field's norm, ends the run (exit 4).")
      .optional("convergence", Schema::sequence(convergence_measure_schema()),
                "Implicit schemes: the convergence measures, at least one.")
      .optional("acceleration", acceleration_schema().default_value("{}"),
                "Implicit schemes: how iterates are updated (default: iqn-ils with its defaults).");
  return s;
}

Schema make_job_schema() {
  Schema s = Schema::file("job",
                          "A coupled run: participants, the fields they exchange, and "
                          "the coupling windows.");
  s.required("name", Schema::string().non_empty(),
             "Name of the job (used in logs, reports and the job id): up to 100 letters, digits, "
             "'.', '_' and '-'.")
      .optional("start_time", Schema::number().non_negative().unit("s").default_value("0"),
                "Simulated start time.")
      .required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .required("window", Schema::number().positive().unit("s"),
                "Coupling window; participants sub-cycle their own steps inside it.")
      .optional("transport", Schema::one_of({"zmq", "mpi"}).default_value("zmq"),
                "How fields travel between processes.")
      .optional("zmq", zmq_schema().default_value("{}"), "ZeroMQ options.")
      .optional("extrapolation", Schema::one_of({"constant", "linear"}).default_value("constant"),
                "How a participant sees its partner's fields inside a window.")
      .optional("window_timeout", Schema::number().range(1e-3, 1e6).unit("s").default_value("600"),
                "Longest wall time a window may take before a participant is declared hung; "
                "also how long participants may take to exit after the last window.")
      .required("participants", Schema::map_of(participant_schema()).length(1, 64),
                "The solver processes, by name (up to 64 letters, digits, '_' and '-'; also the "
                "name of each one's output directory).")
      .optional("exchange", Schema::sequence(exchange_schema()).default_value("[]"),
                "The fields exchanged each window.")
      .optional("momentum_exchange", momentum_exchange_schema().default_value("none"),
                "Implicit drag exchange between a fluid and a porous solid, solved by the "
                "coupler each window; both read the momentum they receive as "
                "'momentum_exchange_impulse'.")
      .optional("energy_exchange", energy_exchange_schema().default_value("none"),
                "Implicit heat exchange between a fluid and a solid, solved by the coupler each "
                "window; both read the heat they receive as 'heat_exchange_energy'.")
      .optional("coupling", coupling_schema().default_value("{}"),
                "The coupling scheme: explicit or implicit, convergence and acceleration.")
      .optional("stability_check", stability_check_schema().default_value("{}"),
                "The explicit coupling's window against its stability bound.")
      .optional("output", output_schema().default_value("{}"), "Coupler output.");
  return s;
}

}  // namespace

const config::Schema& job_schema() {
  static const Schema schema = make_job_schema();
  return schema;
}

std::string job_help() {
  return job_schema().help("Job file (kind: job)") + "\n" +
         exchange::DragLawRegistry::instance().help();
}

}  // namespace cosim::job

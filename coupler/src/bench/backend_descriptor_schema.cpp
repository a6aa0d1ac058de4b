#include "bench/backend_descriptor.hpp"
#include "cosim/fields.hpp"

namespace cosim::bench {

using config::Schema;

namespace {

Schema field_name() {
  std::vector<std::string> names;
  for (const auto* f : fields::all()) names.emplace_back(f->name);
  return Schema::one_of(std::move(names));
}

Schema mesh_kind() {
  return Schema::one_of({"uniform_grid", "nonuniform_line", "point_cloud", "cell_cloud"});
}

Schema kind_rule_schema() {
  Schema s = Schema::object("A condition under which the mesh is of another kind.");
  s.optional("soil_dimension", Schema::integer().range(1, 3), "The soil case's dimension is this.")
      .optional("case_has", Schema::string().non_empty(),
                "The participant's case has this key (e.g. `directory`: a user's own case).")
      .required("kind", mesh_kind(), "The mesh's kind then.");
  return s;
}

Schema mesh_schema() {
  Schema s = Schema::object("The mesh the participant declares for the pairing.");
  s.required("name", Schema::string().non_empty(), "Its name (as the program declares it).")
      .required("kind", mesh_kind(), "Its kind.")
      .required("dimension", Schema::one_of({"same_as_soil", "one_below_soil"}),
                "Its dimension from the soil case's: the same (a grid overlapping the soil's) "
                "or one below (a surface).")
      .optional("kind_when", Schema::sequence(kind_rule_schema()),
                "Rules replacing `kind`; the first that matches wins.");
  return s;
}

Schema crossing_schema() {
  Schema s = Schema::object("A field crossing in the job's `exchange` list.");
  s.required("field", field_name(), "The field (cosim help-fields).")
      .optional("mapping",
                Schema::one_of({"consistent", "conservative"}).default_value("consistent"),
                "How its values move between the meshes.");
  return s;
}

Schema fluid_pairing_schema() {
  Schema s = Schema::object(
      "The backend as the fluid of a pairing with the MPM soil (a suite's `fluid:` runs).");
  s.required("kind", Schema::one_of({"porous", "bed"}),
             "porous: the soil's exchange grid overlaps the fluid's cells; bed: the soil's top "
             "surface is the fluid's bed.")
      .required("mesh", mesh_schema(), "The fluid's mesh.")
      .required("writes", Schema::sequence(field_name()), "Fields the fluid writes.")
      .required("reads", Schema::sequence(field_name()), "Fields the fluid reads.")
      .optional("optional_reads", Schema::sequence(field_name()),
                "Fields it also reads when a scenario's coupling.optional_reads asks.")
      .required("from_soil", Schema::sequence(crossing_schema()),
                "Fields the job maps from the soil to the fluid.")
      .required("to_soil", Schema::sequence(crossing_schema()),
                "Fields the job maps from the fluid to the soil.")
      .optional("momentum_exchange", Schema::one_of({"fluid", "coupler"}),
                "Who solves the drag (the job's momentum_exchange.solved_by) on the fluid's "
                "mesh; absent: no momentum exchange.")
      .optional("case_settings", Schema::map_of(Schema::any()),
                "Keys set in the fluid's case (dotted paths), e.g. {coupling.drag: ice}.");
  return s;
}

Schema soil_pairing_schema() {
  Schema s = Schema::object("The soil's side of one pairing kind.");
  s.required("mesh", mesh_schema(), "The soil's mesh.")
      .required("writes", Schema::sequence(field_name()), "Fields the soil always writes.")
      .required("reads", Schema::sequence(field_name()), "Fields the soil always reads.")
      .required("case_block", Schema::string().non_empty(),
                "The block of the soil's case (dotted) that receives its writes and reads.")
      .optional("case_removes", Schema::sequence(Schema::string().non_empty()),
                "Blocks of other pairings dropped from the soil's case (dotted).")
      .optional("case_requires", Schema::string().non_empty(),
                "A key the soil's case must have (dotted).")
      .optional("case_requires_why", Schema::string(), "The message when it lacks it.");
  return s;
}

Schema stored_field_schema() {
  Schema s = Schema::object("A dataset and its component.");
  s.required("dataset", Schema::string().non_empty(), "The dataset's name in the snapshots.")
      .optional("component", Schema::integer().range(0, 8).default_value("0"), "Its component.");
  return s;
}

Schema outputs_schema() {
  Schema s = Schema::object("Where the backend's outputs live, in the bench's vocabulary.");
  s.optional("snapshots", Schema::string().non_empty(),
             "Base name of the field snapshots (<name>.xdmf and its HDF5 files).")
      .optional(
          "fields",
          Schema::map_of(Schema::any_of({Schema::string().non_empty(), stored_field_schema()})),
          "The bench's fields (pressure, density, velocity_x, velocity_y, water_fraction, "
          "depth, free_surface, temperature) as datasets: a name, or {dataset, "
          "component}.")
      .optional("front_field", Schema::string().non_empty(),
                "The field a water front thresholds (one of `fields`).")
      .optional("gauge_file", Schema::string().non_empty(), "The gauges' CSV file.")
      .optional("gauge_columns", Schema::map_of(Schema::string().non_empty()),
                "Column headers by variable (pressure, velocity_x, ..., depth, speed), {gauge} "
                "standing for the gauge's name: `p_{gauge} [Pa]`.");
  return s;
}

Schema make_backend_schema() {
  Schema s = Schema::file("bench_backend",
                          "What `cosim bench` knows of one backend: its program, its pairing "
                          "with the MPM soil and where its outputs live.");
  s.required("name", Schema::string().non_empty(), "The backend's name in bench suites.")
      .optional("about", Schema::string(), "One line on what it is.")
      .required("executable", Schema::string().non_empty(),
                "Its program (next to cosim, on PATH, or a path).")
      .optional("case_kind", Schema::string().non_empty(),
                "The kind of its standalone case (run as `<executable> --config`); absent: it "
                "runs only ready jobs.")
      .optional("ranks",
                Schema::one_of({"mpi_ranks", "solver_processes"}).default_value("mpi_ranks"),
                "What a job participant's `ranks: N` means for its program: N MPI ranks of it "
                "in the job's MPMD launch (mpi_ranks), or one process of it that starts its "
                "solver on N processes itself (solver_processes, on either transport).")
      .optional("outputs", outputs_schema(), "Where its outputs live.")
      .optional("fluid_pairing", fluid_pairing_schema(),
                "Its side of a pairing as the fluid coupled to the MPM soil.")
      .optional("soil_pairings", Schema::map_of(soil_pairing_schema()),
                "Its side of each pairing kind (porous, bed) as the soil.");
  return s;
}

}  // namespace

const config::Schema& backend_descriptor_schema() {
  static const Schema schema = make_backend_schema();
  return schema;
}

}  // namespace cosim::bench

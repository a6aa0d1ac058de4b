#pragma once

#include <limits>
#include <string>
#include <vector>

#include "cosim/config/schema.hpp"

namespace cosim::config::testing {

// A job-like schema exercising every kind of node the config library knows;
// the real job schema lives with the coupler.
inline Schema example_job_schema() {
  Schema participant = Schema::object("One process of the coupled run.");
  participant.required("executable", Schema::string().non_empty(), "Program to start.")
      .required("config", Schema::path(), "Its own YAML file, relative to this one.");

  Schema kernel_mapping = Schema::object("Mapping with an explicit kernel.");
  kernel_mapping
      .required("constraint", Schema::one_of({"consistent", "conservative"}),
                "What the mapping preserves.")
      .optional("kernel", Schema::one_of({"linear", "gimp"}).default_value("linear"),
                "Interpolation kernel.");

  Schema exchange = Schema::object("One field sent from one participant to another.");
  exchange.required("from", Schema::string(), "Writing participant.")
      .required("to", Schema::string(), "Reading participant.")
      .required("field", Schema::string(), "Field name.")
      .required("mapping",
                Schema::any_of({Schema::one_of({"consistent", "conservative"}), kernel_mapping}),
                "How the field moves between meshes.");

  Schema momentum = Schema::object("Implicit drag exchange.");
  momentum.required("mesh", Schema::string(), "Participant whose mesh carries the exchange.")
      .optional("drag",
                Schema::one_of({"kozeny_carman", "forchheimer"}).default_value("kozeny_carman"),
                "Drag law.");

  Schema job = Schema::file("job", "A coupled run of several participants.");
  job.required("name", Schema::string().non_empty(), "Run name.")
      .required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
      .required("window", Schema::number().positive().unit("s"), "Coupling window length.")
      .optional("transport", Schema::one_of({"zmq", "mpi"}).default_value("zmq"),
                "How fields travel between processes.")
      .optional("gravity", Schema::vector(1, 3).unit("m/s^2").default_value("[0, 0, -9.81]"),
                "Gravitational acceleration vector.")
      .optional("relaxation", Schema::number().range(0.0, 1.0).default_value("1"),
                "Under-relaxation factor of implicit coupling.")
      .optional("max_iterations", Schema::integer().positive().default_value("1"),
                "Coupling iterations per window.")
      .optional("restart", Schema::boolean().default_value("false"), "Resume from a checkpoint.")
      .required("participants",
                Schema::map_of(participant).length(1, std::numeric_limits<std::size_t>::max()),
                "The coupled processes, by name.")
      .optional("exchange", Schema::sequence(exchange), "Fields that cross between participants.")
      .optional("momentum_exchange", Schema::any_of({Schema::one_of({"none"}), momentum}),
                "Implicit momentum exchange, or none.");
  return job;
}

inline std::vector<std::string> valid_job_lines() {
  return {
      "kind: job",                                                                // 1
      "name: clay",                                                               // 2
      "end_time: 5.0",                                                            // 3
      "window: 1.0e-3",                                                           // 4
      "transport: zmq",                                                           // 5
      "gravity: [0, -9.81]",                                                      // 6
      "participants:",                                                            // 7
      "  soil:  {executable: mpm_solver, config: mpm/clay.yaml}",                 // 8
      "  water: {executable: swe_fluid,  config: swe/tank.yaml}",                 // 9
      "exchange:",                                                                // 10
      "  - {from: soil, to: water, field: bed_elevation, mapping: consistent}",   // 11
      "  - {from: water, to: soil, field: bed_traction, mapping: conservative}",  // 12
      "momentum_exchange: {mesh: water, drag: kozeny_carman}",                    // 13
  };
}

}  // namespace cosim::config::testing

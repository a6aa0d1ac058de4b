#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosim/config/schema.hpp"

// What `cosim bench` knows of one backend, read at run time from its
// descriptor (`kind: bench_backend`), which the backend's own folder owns
// (fluid_adapters/<backend>/backend.yaml, mpm_solver/backend.yaml,
// coupler/backend.yaml) and registers with one line,
// cosim_register_backend(<name> <file>), architecture.md §11.4. The bench
// links no solver: everything it needs of one is here, as data.
namespace cosim::bench {

// How many dimensions a pairing's mesh has, from the soil case's.
enum class MeshDimension { same_as_soil, one_below_soil };

// A mesh of a pairing: its name, kind and dimension. The first rule of
// `kind_when` that matches replaces `kind` (e.g. a 1D line under a 2D soil,
// a cloud of cells for a user's own OpenFOAM case).
struct PairingMesh {
  struct KindRule {
    std::optional<int> soil_dimension;  // the soil case's dimension is this
    std::string case_has;               // the participant's case has this key
    std::string kind;
  };
  std::string name;
  std::string kind;
  MeshDimension dimension = MeshDimension::same_as_soil;
  std::vector<KindRule> kind_when;
};

// One field crossing between the two participants through the job's
// `exchange` list.
struct Crossing {
  std::string field;
  std::string mapping = "consistent";
};

// The fluid's side of its pairing with the MPM soil.
//   porous  the soil's exchange grid overlaps the fluid's cells: solid
//           fraction and velocity up, pore pressure down, the drag solved in
//           a momentum exchange on the fluid's mesh (architecture.md §4);
//   bed     the soil's top surface is the fluid's bed: bed elevation up,
//           bed traction down (Zheng et al., Algorithm 1).
struct FluidPairing {
  std::string kind;  // porous | bed, a key of the soil's `soil_pairings`
  PairingMesh mesh;
  std::vector<std::string> writes;
  std::vector<std::string> reads;
  // Fields it also reads when a scenario's `optional_reads` asks (the soil
  // then writes them).
  std::vector<std::string> optional_reads;
  std::vector<Crossing> from_soil;
  std::vector<Crossing> to_soil;
  std::optional<std::string> momentum_exchange_solved_by;  // none: no momentum exchange
  // Keys set in the fluid's case (dotted paths), in order.
  std::vector<std::pair<std::string, YAML::Node>> case_settings;
};

// The soil's side of one pairing kind: its mesh, the fields it always
// writes and reads, and the block of its case that lists them.
struct SoilPairing {
  PairingMesh mesh;
  std::vector<std::string> writes;
  std::vector<std::string> reads;
  std::string case_block;                 // dotted: receives `writes` and `reads`
  std::vector<std::string> case_removes;  // blocks of other pairings, dropped
  std::string case_requires;              // a key the soil's case must have
  std::string case_requires_why;
};

// A field of the bench's vocabulary (pressure, water_fraction, depth...) as
// the backend's snapshots store it.
struct StoredField {
  std::string dataset;
  int component = 0;
};

struct BackendDescriptor {
  std::string name;
  std::string about;
  std::filesystem::path file;  // the descriptor, for messages
  std::string executable;
  std::string case_kind;  // empty: no standalone case (runs only ready jobs)
  // A job participant's `ranks` are the processes its program starts its
  // solver on, not MPI ranks of the program (openfoam_adapter).
  bool ranks_are_solver_processes = false;

  std::string snapshots;  // base name of the field snapshots; empty: none
  std::map<std::string, StoredField> fields;
  std::string front_field;  // what water_front thresholds
  std::string gauge_file;   // empty: no gauges
  // Column headers of gauges.csv by variable, `{gauge}` standing for the
  // gauge's name.
  std::map<std::string, std::string> gauge_columns;

  std::optional<FluidPairing> fluid_pairing;
  std::map<std::string, SoilPairing> soil_pairings;

  bool has_standalone_case() const { return !case_kind.empty(); }
  bool is_fluid() const { return fluid_pairing.has_value(); }
  bool is_soil() const { return !soil_pairings.empty(); }

  // Each throws Error (exit 2) naming the backend and its descriptor when
  // the backend does not record what is asked.
  std::string gauge_file_name() const;
  std::string gauge_column(const std::string& gauge, const std::string& variable) const;
  std::string snapshot_base() const;
  StoredField stored_field(const std::string& field) const;
};

// Reads and validates a descriptor in full; errors are InputErrors at
// `file:line:col: key`.
BackendDescriptor load_backend_descriptor(const std::filesystem::path& file);

const config::Schema& backend_descriptor_schema();

}  // namespace cosim::bench

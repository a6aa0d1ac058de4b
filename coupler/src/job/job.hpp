#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "com/handshake.hpp"
#include "cosim/config/schema.hpp"
#include "cosim/error.hpp"
#include "cosim/mesh.hpp"
#include "job/coupling_spec.hpp"
#include "mapping/constraint.hpp"

// A coupled run as its YAML `kind: job` file describes it, validated in full
// before anything starts.
namespace cosim::job {

struct MeshSpec {
  MeshKind kind = MeshKind::uniform_grid;
  int dim = 1;
  SourceLocation where;
};

struct ParticipantSpec {
  std::string name;
  std::string executable;  // as written: a name looked up next to cosim, then on PATH, or a path
  std::optional<std::filesystem::path> config;  // resolved from the job file's directory
  std::vector<std::string> args;
  std::map<std::string, MeshSpec> meshes;
  std::map<std::string, std::string> writes;  // field -> mesh
  std::map<std::string, std::string> reads;   // field -> mesh
  int ranks = 1;  // MPI ranks of the participant's program (transport: mpi only when > 1)
  // > 0 for a program that runs as one process and starts its solver's
  // processes itself (openfoam_adapter's OpenFOAM): the job's `ranks` is
  // this count, passed as --cosim-solver-processes, and `ranks` is 1.
  int solver_processes = 0;
  SourceLocation ranks_where;  // of the `ranks` key (line 0 when the default)
  SourceLocation where;
};

struct MappingSpec {
  mapping::Constraint constraint = mapping::Constraint::consistent;
  mapping::Kernel kernel = mapping::Kernel::linear;
  std::optional<std::pair<double, double>> bounds;  // bounded fractions
};

struct ExchangeSpec {
  std::string field;
  std::string from;
  std::string to;
  MappingSpec mapping;
  SourceLocation where;
  std::string key_path;
};

enum class TransportKind { zmq, mpi };

// The settings of a job as load_job reads them; the defaults of optional
// keys are the job schema's (job_schema.cpp), never repeated here.
struct ZmqSpec {
  std::string scheme;  // ipc | tcp
  std::string host;
  bool allow_non_loopback = false;
};

// Who solves the implicit momentum exchange of a fluid and a porous solid:
//   coupler  once per window on the exchange mesh; both phases read the
//            momentum they receive (architecture.md §4);
//   fluid    the fluid, inside each of its own steps (Tran et al., MPMICE,
//            eqs. 48 and 67-68 with the solid as one of the materials): the
//            coupler evaluates the drag law once per window and sends K as
//            `drag_coefficient`; the fluid writes the momentum the solid
//            receives as `momentum_exchange_impulse`, which the coupler maps
//            conservatively to the solid. The drag is then implicit at the
//            fluid's time step (Darcy flow and the pressure it needs are right
//            at any window length) instead of once per window.
enum class ExchangeSolver { coupler, fluid };

// The implicit momentum exchange between a fluid and a porous solid on the
// cells of one participant's mesh (architecture.md §4). The phases' fields have
// fixed names (cosim/fields.hpp).
struct MomentumExchangeSpec {
  std::string fluid;
  std::string solid;
  std::string mesh_owner;  // participant whose mesh is the exchange mesh
  std::string mesh;
  YAML::Node drag;  // the drag law's map, checked by exchange::make_drag_law
  std::string drag_key_path = "momentum_exchange.drag";
  ExchangeSolver solved_by = ExchangeSolver::coupler;
  SourceLocation where;
};

// The implicit energy exchange between a fluid and a solid sharing cells
// (Tran et al., MPMICE, eq. 23), solved by the coupler once per window on
// one participant's mesh with a heat exchange coefficient H: per unit
// volume the fluid receives
//   q = (T_s - T_f) / (1 / (dt H) + 1 / C_f + 1 / C_s),  C = rhobar c,
// and the solid -q, so the phases' temperatures relax implicitly and the
// energy is conserved to round-off. Field names in cosim/fields.hpp.
struct EnergyExchangeSpec {
  std::string fluid;
  std::string solid;
  std::string mesh_owner;
  std::string mesh;
  double coefficient = 0.0;  // H [W m^-3 K^-1]
  SourceLocation where;
};

// How the coupler treats a window longer than the explicit coupling's
// stability bound (architecture.md §3): it warns above the bound, and refuses the
// run before its first window above `refuse_above` times the bound, unless
// the job accepts it.
struct StabilityCheck {
  double refuse_above = 0.0;
  bool accept_unstable = false;
};

struct Job {
  std::filesystem::path file;
  std::string name;
  std::string config_hash;  // of the job file and every participant config it names
  // The same with every participant's `ranks` value left out: a checkpoint
  // restarts with the participants on other counts of ranks.
  std::string config_hash_without_ranks;
  double start_time = 0.0;
  double end_time = 0.0;
  double window = 0.0;
  SourceLocation window_where;  // of the `window` key, for messages about it
  StabilityCheck stability;
  CouplingSpec coupling;
  TransportKind transport = TransportKind::zmq;
  ZmqSpec zmq;
  com::Extrapolation extrapolation = com::Extrapolation::constant;
  double window_timeout_s = 0.0;
  double output_every = 0.0;                  // 0: no snapshots of the exchanged fields
  std::vector<ParticipantSpec> participants;  // in file order
  std::vector<ExchangeSpec> exchanges;
  std::optional<MomentumExchangeSpec> momentum_exchange;
  std::optional<EnergyExchangeSpec> energy_exchange;

  const ParticipantSpec* participant(const std::string& name) const;
  std::size_t windows() const;  // number of coupling windows
};

// The schema of `kind: job` files.
const config::Schema& job_schema();
// `cosim help-config`: the job's keys, then each drag law's.
std::string job_help();

// Loads, validates (schema, then cross-references: unknown participants,
// fields read that nobody writes, mismatched mesh dimensions, ...) and
// returns the job. Throws InputError with file, line, column and key path.
// A participant whose executable's file name is among
// `programs_starting_their_processes` takes its `ranks` as its solver's
// processes (ParticipantSpec::solver_processes), on either transport.
Job load_job(const std::filesystem::path& file,
             const std::set<std::string>& programs_starting_their_processes = {});

}  // namespace cosim::job

#pragma once

#include <string>
#include <vector>

#include "com/message.hpp"
#include "cosim/field.hpp"
#include "cosim/mesh.hpp"

// What a participant and the coupler say to each other before the first
// window, and how meshes travel (JSON for declarations, float64 for
// geometry).
namespace cosim::com {

struct MeshDeclaration {
  std::string name;
  MeshKind kind = MeshKind::uniform_grid;
  int dim = 1;
};

struct Hello {
  std::string participant;
  std::string config_hash;
  // The secret the coupler handed this participant's process (never on a
  // command line); the coupler admits a hello only with the right one.
  std::string token;
  std::string program;
  long pid = 0;
  std::vector<MeshDeclaration> meshes;
  std::vector<FieldSpec> writes;
  std::vector<FieldSpec> reads;
  // The solver saves its state at a window's start and can run the window
  // again from it (Participant::declare_repeatable); implicit schemes need it.
  bool repeatable = false;
  // It can write its state into a checkpoint and start again from one
  // (Participant::declare_checkpointable).
  bool checkpointable = false;
  // Started from a checkpoint: the last window it holds (0: a fresh start).
  std::uint64_t restart_window = 0;
  // A participant on several ranks says hello from each: this rank's part
  // and how many there are (m2n::PartitionedHub merges them into one).
  int part = 0;
  int parts = 1;
  // Its meshes are declared in parts (Participant::declare_mesh with a
  // MeshPart); a program on several ranks that declares them whole cannot
  // run so in a coupled job.
  bool partitioned = false;
};

enum class Extrapolation { constant, linear };
// What an implicit scheme's participant reads inside a window, between the
// converged values at its start and the current iterate at its end.
enum class TimeInterpolation { constant, linear };

struct Welcome {
  std::string config_hash;  // the job's; the participant checks it against its own
  double start_time = 0.0;
  double end_time = 0.0;
  double window = 0.0;
  Extrapolation extrapolation = Extrapolation::constant;
  // Implicit schemes: windows may be repeated (window_repeat), and the
  // fields received are iterates of the values at the window's end.
  bool implicit = false;
  TimeInterpolation time_interpolation = TimeInterpolation::constant;
  double timeout_s = 600.0;        // longest wait for the coupler (beyond its own window timeout)
  std::vector<std::string> sends;  // the participant's reads the job sends it
};

std::string to_json(const Hello& hello);
std::string to_json(const Welcome& welcome);
// Parse and check; a malformed text is a ProtocolError naming `peer`.
Hello parse_hello(const std::string& text, const std::string& peer);
Welcome parse_welcome(const std::string& text, const std::string& peer);

Message make_mesh_message(const std::string& job_id, const std::string& sender,
                          std::uint64_t window, double time, const Mesh& mesh);
// Rebuilds and validates the mesh; errors are ProtocolErrors naming `peer`.
Mesh decode_mesh_message(const Message& message, const std::string& peer);

}  // namespace cosim::com

#include "cosim/participant.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>

#include "com/handshake.hpp"
#include "com/mpi_transport.hpp"
#include "com/zmq_transport.hpp"
#include "cosim/error.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/runtime/stop_request.hpp"

namespace cosim {

using com::MessageType;
using Clock = std::chrono::steady_clock;

namespace {

// Steps that end within this fraction of a window from its end complete it.
constexpr double window_end_tolerance = 1e-9;
constexpr const char* token_variable = "COSIM_TOKEN";
// A wait for the coupler wakes this often to look for a stop request.
constexpr auto stop_check_interval = std::chrono::milliseconds(100);

// The directory part `part` of a participant on `parts` ranks writes its
// part of a checkpoint into, in the participant's directory `dir`.
std::filesystem::path part_directory(const std::filesystem::path& dir, int part, int parts) {
  return parts > 1 ? dir / fmt::format("rank_{}", part) : dir;
}

// The parts a participant's directory of a checkpoint holds, in rank order.
std::vector<std::filesystem::path> checkpoint_parts(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> parts;
  for (int r = 0; std::filesystem::is_directory(part_directory(dir, r, 2)); ++r)
    parts.push_back(part_directory(dir, r, 2));
  if (parts.empty()) parts.push_back(dir);
  return parts;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

[[noreturn]] void usage_error(const std::string& participant, const std::string& what) {
  throw Error(ExitCode::bad_input, fmt::format("participant '{}': {}", participant, what));
}

}  // namespace

void add_coupling_options(CLI::App& app, CouplingEndpoint& endpoint) {
  auto* group = app.add_option_group("coupling", "Set by `cosim run`; absent when standalone");
  group->add_option("--cosim-endpoint", endpoint.uri,
                    "coupler address (ipc://..., tcp://127.0.0.1:port, mpi://)");
  group->add_option("--cosim-name", endpoint.name, "this participant's name in the job");
  group->add_option("--cosim-job", endpoint.job_id, "id of the job this process belongs to");
  group->add_option("--cosim-config-hash", endpoint.config_hash, "hash of the job's config");
  group
      ->add_option("--cosim-connect-timeout", endpoint.connect_timeout_s,
                   "seconds to wait for the coupler's welcome")
      ->check(CLI::Range(0.1, 1.0e6));
  group->add_flag("--cosim-repeat-windows", endpoint.repeat_windows,
                  "standalone: run every window twice, going back to its start once (checks "
                  "the solver's save and restore)");
  group->add_option("--cosim-restart", endpoint.restart,
                    "this participant's directory of the checkpoint to start from");
  group
      ->add_option("--cosim-solver-processes", endpoint.solver_processes,
                   "the processes to run the solver on (the job's `ranks` of a program that "
                   "starts its solver's processes itself)")
      ->check(CLI::Range(1, 100000));
}

struct WriteBuffer {
  FieldSpec spec;
  std::vector<double> values;  // state: last written; integral: the rate last written
  std::vector<double> integral;
  bool written = false;
};

struct ReadBuffer {
  FieldSpec spec;
  std::vector<double> current;
  std::vector<double> previous;  // for linear extrapolation
  std::vector<double> start;     // the accepted values at the window's start time
  double received_at = 0.0;
  double previous_at = 0.0;
  bool has_previous = false;
  std::vector<double> delivered;  // integral fields: shares handed out this window
};

struct MeshEntry {
  Mesh mesh;
  std::optional<MeshPart> part;  // this rank's, on a participant on several ranks
  bool changed = true;

  // The values a field on this mesh holds per component on this rank.
  std::size_t values() const { return part ? part->size() : mesh.size(); }
};

// A part names elements of its mesh, each once: a grid's values, or one per
// element of a cloud's part.
void check_part(const std::string& participant, const Mesh& mesh, const MeshPart& part) {
  const bool whole_geometry = mesh.kind() == MeshKind::uniform_grid;
  if (!part.owned.empty() && part.owned.size() != part.size())
    usage_error(participant, fmt::format("the part of mesh '{}' says of {} of its {} elements "
                                         "whether it owns them",
                                         mesh.name, part.owned.size(), part.size()));
  if (!whole_geometry && part.has_ghosts())
    usage_error(participant,
                fmt::format("the part of cloud '{}' has ghosts: a cloud's part is the points "
                            "the rank owns",
                            mesh.name));
  if (!whole_geometry && part.size() != mesh.size())
    usage_error(participant,
                fmt::format("mesh '{}' has {} elements on this rank, its part names {}", mesh.name,
                            mesh.size(), part.size()));
  std::vector<std::int64_t> sorted = part.elements;
  std::sort(sorted.begin(), sorted.end());
  if (!sorted.empty() && sorted.front() < 0)
    usage_error(participant,
                fmt::format("the part of mesh '{}' names element {}", mesh.name, sorted.front()));
  if (whole_geometry && !sorted.empty() && sorted.back() >= static_cast<std::int64_t>(mesh.size()))
    usage_error(participant, fmt::format("the part of mesh '{}' names element {} of {}", mesh.name,
                                         sorted.back(), mesh.size()));
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    usage_error(participant,
                fmt::format("the part of mesh '{}' names an element twice", mesh.name));
}

struct Participant::Impl {
  std::string name;
  CouplingEndpoint endpoint;
  std::unique_ptr<com::Transport> transport;
  std::map<std::string, MeshEntry, std::less<>> meshes;
  std::map<std::string, WriteBuffer, std::less<>> writes;
  std::map<std::string, ReadBuffer, std::less<>> reads;
  com::Welcome schedule;
  bool initialized = false;
  bool admitted = false;  // the coupler welcomed this participant
  bool finished = false;  // the coupler said the run is over
  bool finalized = false;
  double time = 0.0;
  std::size_t window = 0;
  double standalone_window = 0.0;
  CouplingTimings timings;
  bool repeatable = false;
  std::size_t iteration = 1;
  bool save_state = false;
  bool restore_state = false;
  bool window_complete = false;
  bool repeat_requested = false;  // the coupler's window_repeat
  bool checkpointable = false;
  bool restartable_on_other_ranks = false;
  std::filesystem::path checkpoint_directory;  // this rank's, asked for by the last window_begin
  std::filesystem::path restart_directory;     // this rank's part, after initialize()
  std::vector<std::filesystem::path> restart_parts;
  bool stop_after_checkpoint = false;
  bool write_checkpoint = false;

  std::size_t size_of(const FieldSpec& f) const {
    return meshes.at(f.mesh).values() * static_cast<std::size_t>(f.components);
  }
  // This rank's part and the participant's ranks, from the transport (one
  // part standalone and over ZeroMQ).
  int part = 0;
  int parts = 1;

  // Computed from the window's index, as the coupler does, never accumulated:
  // over thousands of windows a running sum drifts past the coupler's tolerance.
  double window_end() const { return window_time(window); }
  double window_start() const { return window_time(window - 1); }
  double window_time(std::size_t w) const {
    return std::min(schedule.end_time,
                    schedule.start_time + static_cast<double>(w) * schedule.window);
  }
  // Whether windows run more than once: an implicit job, or a standalone
  // check of save and restore.
  bool repeats_windows() const { return schedule.implicit || endpoint.repeat_windows; }

  void send(com::Message message) {
    const auto start = Clock::now();
    transport->send(com::coupler_peer, message);
    timings.transport += seconds_since(start);
  }

  com::Message header_only(MessageType type) const {
    com::Message m;
    m.header.type = type;
    m.header.job_id = endpoint.job_id;
    m.header.sender = name;
    m.header.window = window;
    m.header.time = time;
    return m;
  }

  // Waits for the coupler's next message; a silent coupler is an error after
  // the timeout, an abort from it ends this participant.
  com::Message receive(double timeout_s) {
    const auto start = Clock::now();
    const auto deadline = start + std::chrono::milliseconds(static_cast<long>(timeout_s * 1000.0));
    std::optional<com::Received> received;
    // An empty receive before the deadline is a signal's wake-up or a slice
    // ending: look for a stop request and wait on.
    while (!received && Clock::now() < deadline) {
      runtime::throw_if_stop_requested();
      const auto slice = std::min<Clock::duration>(deadline - Clock::now(), stop_check_interval);
      received = transport->receive(std::chrono::ceil<std::chrono::milliseconds>(slice));
    }
    timings.waiting += seconds_since(start);
    if (!received)
      throw ProtocolError(com::coupler_peer,
                          fmt::format("no answer within {} s (participant '{}', window {})",
                                      timeout_s, name, window));
    com::Message& m = received->message;
    // A refusal carries the coupler's job id, which may be the very reason.
    if (m.header.type == MessageType::refuse)
      throw Error(ExitCode::bad_input,
                  fmt::format("the coupler refused participant '{}': {}", name, m.payload.text()));
    if (m.header.job_id != endpoint.job_id)
      throw ProtocolError(com::coupler_peer, fmt::format("message for job '{}', this is job '{}'",
                                                         m.header.job_id, endpoint.job_id));
    if (m.header.sender != com::coupler_peer)
      throw ProtocolError(
          com::coupler_peer,
          fmt::format("message signed by '{}', not by the coupler", m.header.sender));
    if (m.header.type == MessageType::abort)
      throw Error(ExitCode::participant_failed,
                  fmt::format("the coupler aborted the run: {}", m.payload.text()));
    return std::move(m);
  }

  // The abort message: the reason, and the exit code this process ends
  // with (in the header's field name), when it ends on a cosim::Error.
  com::Message abort_message(std::string_view reason) const {
    com::Message m =
        com::make_text_message(MessageType::abort, endpoint.job_id, name, window, time, reason);
    ExitCode code = ExitCode::participant_failed;
    if (std::current_exception()) {
      try {
        throw;
      } catch (const Error& e) {
        code = e.code();
      } catch (...) {
        code = ExitCode::internal_error;
      }
    }
    m.header.field = to_string(code);
    return m;
  }

  void send_window_data() {
    for (auto& [mesh_name, entry] : meshes) {
      if (!entry.changed) continue;
      if (parts > 1) send(part_message(entry));
      send(com::make_mesh_message(endpoint.job_id, name, window, time, entry.mesh));
      entry.changed = false;
    }
    for (auto& [field_name, w] : writes) {
      const auto& values = w.spec.time == TimeTreatment::integral ? w.integral : w.values;
      send(com::make_field_message(endpoint.job_id, name, window, time, field_name, w.spec.mesh,
                                   owned_values(w.spec, values),
                                   static_cast<std::uint32_t>(w.spec.components)));
      if (w.spec.time == TimeTreatment::integral)
        std::fill(w.integral.begin(), w.integral.end(), 0.0);
    }
    send(header_only(MessageType::window_end));
  }

  // The values a rank sends of a field: those of the elements it owns.
  std::span<const double> owned_values(const FieldSpec& f, const std::vector<double>& values) {
    const MeshEntry& entry = meshes.at(f.mesh);
    if (!entry.part || !entry.part->has_ghosts() || parts == 1) return values;
    const auto c = static_cast<std::size_t>(f.components);
    owned_buffer.clear();
    for (std::size_t i = 0; i < entry.part->size(); ++i)
      if (entry.part->owns(i))
        owned_buffer.insert(owned_buffer.end(), values.begin() + static_cast<std::ptrdiff_t>(i * c),
                            values.begin() + static_cast<std::ptrdiff_t>((i + 1) * c));
    return owned_buffer;
  }
  std::vector<double> owned_buffer;

  // The part's elements, and with ghosts whether each is owned.
  com::Message part_message(const MeshEntry& entry) const {
    const MeshPart& mine = *entry.part;
    const bool ghosts = mine.has_ghosts();
    std::vector<double> record;
    for (std::size_t i = 0; i < mine.size(); ++i) {
      record.push_back(static_cast<double>(mine.elements[i]));
      if (ghosts) record.push_back(mine.owns(i) ? 1.0 : 0.0);
    }
    com::Message m = com::make_field_message(endpoint.job_id, name, window, time, "",
                                             entry.mesh.name, record, ghosts ? 2u : 1u);
    m.header.type = MessageType::mesh_part;
    return m;
  }

  // Learns this rank's part from an MPI transport. A participant on several
  // ranks declares every mesh with its part (a program that declares them
  // whole says so in its hello, and the coupler refuses it); one on a single
  // rank has none but the whole mesh.
  bool find_part() {
    if (const auto* mpi = dynamic_cast<const com::MpiClient*>(transport.get())) {
      part = mpi->application_rank();
      parts = mpi->application_size();
    }
    bool partitioned = !meshes.empty();
    for (const auto& [mesh_name, entry] : meshes) {
      partitioned = partitioned && entry.part.has_value();
      if (parts == 1 && entry.part) {
        bool whole = !entry.part->has_ghosts() && (entry.part->size() == entry.mesh.size() ||
                                                   entry.mesh.kind() != MeshKind::uniform_grid);
        for (std::size_t i = 0; whole && i < entry.part->size(); ++i)
          whole = entry.part->elements[i] == static_cast<std::int64_t>(i);
        if (!whole)
          usage_error(name, fmt::format("runs on one rank, but declares only a part of mesh '{}'",
                                        mesh_name));
      }
    }
    return partitioned;
  }

  // Receives the mapped fields for the next window, then window_begin or
  // finish; or, in an implicit scheme, the next iterate and window_repeat.
  void receive_window_data() {
    repeat_requested = false;
    for (;;) {
      com::Message m = receive(schedule.timeout_s);
      switch (m.header.type) {
        case MessageType::field:
          store_field(m);
          break;
        case MessageType::window_begin:
          if (m.header.window != window + 1)
            throw ProtocolError(com::coupler_peer, fmt::format("began window {} after window {}",
                                                               m.header.window, window));
          // Values of the new window's start time start its interpolation;
          // values ahead of it (a serial scheme's second participant reads
          // the first's window end) keep the start store_field() gave them.
          for (auto& [field_name, r] : reads)
            if (r.received_at <= window_end() + window_end_tolerance * schedule.window)
              r.start = r.current;
          read_checkpoint_request(m);
          if (!checkpoint_directory.empty() && !checkpointable)
            throw ProtocolError(com::coupler_peer,
                                fmt::format("asked participant '{}', which did not declare it "
                                            "can, for a checkpoint",
                                            name));
          return;
        case MessageType::window_repeat:
          if (!schedule.implicit || m.header.window != window || window == 0)
            throw ProtocolError(
                com::coupler_peer,
                fmt::format("asked to repeat window {} during window {}{}", m.header.window, window,
                            schedule.implicit ? "" : " of an explicit scheme"));
          repeat_requested = true;
          return;
        case MessageType::finish:
          finished = true;
          return;
        default:
          throw ProtocolError(com::coupler_peer,
                              fmt::format("unexpected '{}' message while waiting for window data",
                                          com::to_string(m.header.type)));
      }
    }
  }

  void store_field(const com::Message& m) {
    auto it = reads.find(m.header.field);
    if (it == reads.end())
      throw ProtocolError(com::coupler_peer,
                          fmt::format("sent field '{}', which participant '{}' does not read",
                                      m.header.field, name));
    ReadBuffer& r = it->second;
    if (m.header.mesh != r.spec.mesh ||
        m.header.components != static_cast<std::uint32_t>(r.spec.components) ||
        m.header.count * m.header.components != r.current.size())
      throw ProtocolError(com::coupler_peer,
                          fmt::format("field '{}' arrived as {} x {} on mesh '{}', expected {} "
                                      "values on mesh '{}'",
                                      m.header.field, m.header.count, m.header.components,
                                      m.header.mesh, r.current.size(), r.spec.mesh));
    com::validate_payload(m, com::coupler_peer, r.spec.allow_nonfinite);
    if (m.header.time > r.received_at) r.start = r.current;
    r.previous.swap(r.current);
    r.previous_at = r.received_at;
    r.has_previous = r.spec.time == TimeTreatment::state && r.received_at < m.header.time;
    m.payload.copy_doubles_to(r.current);
    r.received_at = m.header.time;
    std::fill(r.delivered.begin(), r.delivered.end(), 0.0);
  }

  // A window_begin that asks for a checkpoint names its directory, and
  // whether the run stops after it (the coupler was asked to stop).
  void read_checkpoint_request(const com::Message& m) {
    checkpoint_directory.clear();
    stop_after_checkpoint = false;
    if (m.payload.size() == 0) return;
    try {
      const auto request = nlohmann::json::parse(m.payload.text());
      checkpoint_directory =
          part_directory(request.at("checkpoint_directory").get<std::string>(), part, parts);
      stop_after_checkpoint = request.at("then_stop").get<bool>();
    } catch (const nlohmann::json::exception& e) {
      throw ProtocolError(com::coupler_peer,
                          fmt::format("sent a malformed checkpoint request: {}", e.what()));
    }
    std::filesystem::create_directories(checkpoint_directory);
  }

  // This library's part of a checkpoint (architecture.md §14): where the
  // run is, and every field buffer as it stands at a window's start.
  static constexpr const char* state_file_name = "participant.h5";
  static constexpr const char* state_kind = "cosim_participant";
  static constexpr std::int64_t state_version = 1;

  void write_state(const std::filesystem::path& directory) const {
    StateFileWriter out(directory / state_file_name, state_kind, state_version);
    out.integer("window", static_cast<std::int64_t>(window));
    out.number("time", time);
    out.integer("windows_completed", static_cast<std::int64_t>(timings.windows));
    out.integer("window_attempts", static_cast<std::int64_t>(timings.iterations));
    for (const auto& [field, r] : reads) {
      const std::string key = "read." + field + ".";
      out.numbers(key + "current", r.current);
      out.numbers(key + "previous", r.previous);
      out.numbers(key + "start", r.start);
      out.number(key + "received_at", r.received_at);
      out.number(key + "previous_at", r.previous_at);
      out.integer(key + "has_previous", r.has_previous ? 1 : 0);
    }
    for (const auto& [field, w] : writes) {
      const std::string key = "write." + field + ".";
      out.numbers(key + "values", w.values);
      out.numbers(key + "integral", w.integral);
      out.integer(key + "written", w.written ? 1 : 0);
    }
    // Where this rank's values lie in the whole meshes, for a restart on
    // another count of ranks.
    for (const auto& [mesh_name, entry] : meshes) {
      if (!entry.part) continue;
      out.integers("part." + mesh_name + ".elements", entry.part->elements);
      std::vector<std::int64_t> owned(entry.part->size());
      for (std::size_t i = 0; i < owned.size(); ++i) owned[i] = entry.part->owns(i) ? 1 : 0;
      out.integers("part." + mesh_name + ".owned", owned);
    }
    out.commit();
  }

  // Reads the state write_state() left; returns the last window it holds.
  std::size_t read_state(const std::filesystem::path& directory) {
    const StateFileReader in(directory / state_file_name, state_kind, state_version);
    const std::int64_t next_window = in.integer("window");
    if (next_window < 2)
      throw Error(ExitCode::bad_input, fmt::format("{}: window {} cannot follow a checkpoint",
                                                   in.file().string(), next_window));
    window = static_cast<std::size_t>(next_window);
    time = in.number("time");
    timings.windows = static_cast<std::size_t>(in.integer("windows_completed"));
    timings.iterations = static_cast<std::size_t>(in.integer("window_attempts"));
    for (auto& [field, r] : reads) {
      const std::string key = "read." + field + ".";
      const std::size_t n = r.current.size();
      in.numbers(key + "current", n, r.current);
      in.numbers(key + "previous", n, r.previous);
      in.numbers(key + "start", n, r.start);
      r.received_at = in.number(key + "received_at");
      r.previous_at = in.number(key + "previous_at");
      r.has_previous = in.integer(key + "has_previous") != 0;
      std::fill(r.delivered.begin(), r.delivered.end(), 0.0);
    }
    for (auto& [field, w] : writes) {
      const std::string key = "write." + field + ".";
      in.numbers(key + "values", w.values.size(), w.values);
      in.numbers(key + "integral", w.integral.size(), w.integral);
      w.written = in.integer(key + "written") != 0;
    }
    finish_restore();
    return window - 1;
  }

  // The coupler's checkpoint holds the meshes as they were; the parts of a
  // participant on several ranks go to it again, for it to split and join
  // their fields.
  void finish_restore() {
    for (auto& [mesh_name, entry] : meshes) entry.changed = entry.part.has_value();
  }

  // Reads the state the `files` of a checkpoint written on another count of
  // ranks left: the scalars from the first, each field joined into the whole
  // mesh from every part's owned values and this rank's part taken from it.
  std::size_t read_state_of_parts(const std::vector<std::filesystem::path>& directories) {
    std::vector<std::unique_ptr<StateFileReader>> in;
    for (const auto& d : directories)
      in.push_back(
          std::make_unique<StateFileReader>(d / state_file_name, state_kind, state_version));
    const std::int64_t next_window = in[0]->integer("window");
    if (next_window < 2)
      throw Error(ExitCode::bad_input, fmt::format("{}: window {} cannot follow a checkpoint",
                                                   in[0]->file().string(), next_window));
    window = static_cast<std::size_t>(next_window);
    time = in[0]->number("time");
    timings.windows = static_cast<std::size_t>(in[0]->integer("windows_completed"));
    timings.iterations = static_cast<std::size_t>(in[0]->integer("window_attempts"));
    // Where each value this rank holds of a mesh lies in the parts: the part
    // that owns its element (else one that holds it as a ghost) and its
    // index there; found once per mesh.
    struct Source {
      std::size_t file = 0, index = 0;
    };
    std::map<std::string, std::vector<Source>, std::less<>> sources;
    const auto sources_of = [&](const std::string& mesh_name) -> const std::vector<Source>& {
      if (auto it = sources.find(mesh_name); it != sources.end()) return it->second;
      const MeshEntry& entry = meshes.at(mesh_name);
      if (entry.mesh.kind() != MeshKind::uniform_grid)
        throw Error(ExitCode::bad_input,
                    fmt::format("{}: mesh '{}' is a cloud, whose parts are this run's points; a "
                                "restart on another count of ranks needs grids",
                                directories[0].string(), mesh_name));
      constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
      std::vector<Source> in_whole(entry.mesh.size(), Source{none, 0});
      for (const bool owners : {true, false})
        for (std::size_t f = 0; f < in.size(); ++f) {
          // A checkpoint of one rank holds the whole mesh.
          std::vector<std::int64_t> elements(entry.mesh.size()), owned(entry.mesh.size(), 1);
          std::iota(elements.begin(), elements.end(), std::int64_t{0});
          if (in[f]->has("part." + mesh_name + ".elements")) {
            elements = in[f]->integers("part." + mesh_name + ".elements");
            in[f]->integers("part." + mesh_name + ".owned", elements.size(), owned);
          }
          for (std::size_t i = 0; i < elements.size(); ++i) {
            const auto e = static_cast<std::size_t>(elements[i]);
            if ((owned[i] != 0) == owners && e < in_whole.size() && in_whole[e].file == none)
              in_whole[e] = {f, i};
          }
        }
      std::vector<Source> mine(entry.values());
      for (std::size_t i = 0; i < mine.size(); ++i) {
        const auto e = entry.part ? static_cast<std::size_t>(entry.part->elements[i]) : i;
        if (in_whole[e].file == none)
          throw Error(ExitCode::bad_input, fmt::format("{}: no part holds element {} of mesh '{}'",
                                                       directories[0].string(), e, mesh_name));
        mine[i] = in_whole[e];
      }
      return sources.emplace(mesh_name, std::move(mine)).first->second;
    };
    // The array `key` of every part, this rank's values gathered from it.
    const auto part_of = [&](const std::string& key, const std::string& mesh_name, std::size_t c,
                             std::vector<double>& values) {
      const std::vector<Source>& from = sources_of(mesh_name);
      std::vector<std::vector<double>> stored(in.size());
      for (std::size_t f = 0; f < in.size(); ++f) stored[f] = in[f]->numbers(key);
      values.resize(from.size() * c);
      for (std::size_t i = 0; i < from.size(); ++i) {
        const std::vector<double>& array = stored[from[i].file];
        if (array.size() < (from[i].index + 1) * c)
          throw Error(ExitCode::bad_input, fmt::format("{}: array '{}' is shorter than its part",
                                                       in[from[i].file]->file().string(), key));
        std::copy_n(array.begin() + static_cast<std::ptrdiff_t>(from[i].index * c), c,
                    values.begin() + static_cast<std::ptrdiff_t>(i * c));
      }
    };
    for (auto& [field, r] : reads) {
      const std::string key = "read." + field + ".";
      const auto c = static_cast<std::size_t>(r.spec.components);
      part_of(key + "current", r.spec.mesh, c, r.current);
      part_of(key + "previous", r.spec.mesh, c, r.previous);
      part_of(key + "start", r.spec.mesh, c, r.start);
      r.received_at = in[0]->number(key + "received_at");
      r.previous_at = in[0]->number(key + "previous_at");
      r.has_previous = in[0]->integer(key + "has_previous") != 0;
      std::fill(r.delivered.begin(), r.delivered.end(), 0.0);
    }
    for (auto& [field, w] : writes) {
      const std::string key = "write." + field + ".";
      const auto c = static_cast<std::size_t>(w.spec.components);
      part_of(key + "values", w.spec.mesh, c, w.values);
      part_of(key + "integral", w.spec.mesh, c, w.integral);
      w.written = in[0]->integer(key + "written") != 0;
    }
    finish_restore();
    return window - 1;
  }

  // Finds this rank's part of the checkpoint to start from and reads this
  // library's state from it (or from all the parts of another count of ranks).
  std::size_t restore_from_checkpoint() {
    restart_parts = checkpoint_parts(endpoint.restart);
    const int written_by = static_cast<int>(restart_parts.size());
    if (written_by == parts) {
      restart_directory = restart_parts[static_cast<std::size_t>(part)];
      return read_state(restart_directory);
    }
    restart_directory = restart_parts.front();
    if (!restartable_on_other_ranks)
      throw Error(ExitCode::bad_input,
                  fmt::format("{}: participant '{}' wrote this checkpoint on {} rank{}; it runs on "
                              "{} now, and its solver restarts only on as many ranks as wrote the "
                              "checkpoint",
                              endpoint.restart.string(), name, written_by,
                              written_by == 1 ? "" : "s", parts));
    return read_state_of_parts(restart_parts);
  }

  void check_declaration(const FieldSpec& f) const {
    if (f.name.empty()) usage_error(name, "a field has an empty name");
    if (!meshes.count(f.mesh))
      usage_error(name,
                  fmt::format("field '{}' is on mesh '{}', which is not declared", f.name, f.mesh));
    if (writes.count(f.name) || reads.count(f.name))
      usage_error(name, fmt::format("field '{}' is declared twice", f.name));
    if (f.components < 1 || f.components > 9)
      usage_error(name, fmt::format("field '{}' has {} components", f.name, f.components));
    if (initialized) usage_error(name, "fields are declared before initialize()");
  }

  const ReadBuffer& read_buffer(std::string_view field) const {
    auto it = reads.find(field);
    if (it == reads.end()) usage_error(name, fmt::format("reads undeclared field '{}'", field));
    return it->second;
  }
};

Participant::Participant(std::string name, CouplingEndpoint endpoint)
    : impl_(std::make_unique<Impl>()) {
  impl_->name = std::move(name);
  impl_->endpoint = std::move(endpoint);
  if (impl_->name.empty()) throw Error(ExitCode::bad_input, "a participant needs a name");
  if (impl_->endpoint.token.empty() && !impl_->endpoint.is_standalone())
    if (const char* token = std::getenv(token_variable)) impl_->endpoint.token = token;
  ::unsetenv(token_variable);
  // Whoever started a coupled participant (cosim, or mpirun) going away takes
  // it along: a coupled participant never outlives its run.
  if (!impl_->endpoint.is_standalone()) ::prctl(PR_SET_PDEATHSIG, SIGKILL);
}

Participant::~Participant() {
  try {
    if (std::uncaught_exceptions() > 0)
      abort("the solver stopped with an error");
    else
      finalize();
  } catch (...) {
  }
}

const std::string& Participant::name() const {
  return impl_->name;
}
bool Participant::is_coupled() const {
  return !impl_->endpoint.is_standalone();
}

void Participant::declare_mesh(Mesh mesh) {
  if (impl_->initialized) usage_error(impl_->name, "meshes are declared before initialize()");
  validate(mesh);
  if (impl_->meshes.count(mesh.name))
    usage_error(impl_->name, fmt::format("mesh '{}' is declared twice", mesh.name));
  std::string key = mesh.name;
  impl_->meshes.emplace(std::move(key), MeshEntry{std::move(mesh), std::nullopt, true});
}

void Participant::declare_mesh(Mesh mesh, MeshPart part) {
  check_part(impl_->name, mesh, part);
  const std::string mesh_name = mesh.name;
  declare_mesh(std::move(mesh));
  impl_->meshes.at(mesh_name).part = std::move(part);
}

void Participant::declare_write(FieldSpec field) {
  impl_->check_declaration(field);
  const std::size_t n = impl_->size_of(field);
  WriteBuffer w{field, std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), false};
  impl_->writes.emplace(field.name, std::move(w));
}

void Participant::declare_read(FieldSpec field, double default_value) {
  impl_->check_declaration(field);
  const std::size_t n = impl_->size_of(field);
  ReadBuffer r;
  r.spec = field;
  r.current.assign(n, field.time == TimeTreatment::integral ? 0.0 : default_value);
  r.previous = r.current;
  r.start = r.current;
  r.delivered.assign(n, 0.0);
  impl_->reads.emplace(field.name, std::move(r));
}

void Participant::declare_repeatable() {
  if (impl_->initialized)
    usage_error(impl_->name, "declare_repeatable() comes before initialize()");
  impl_->repeatable = true;
}

void Participant::declare_checkpointable() {
  if (impl_->initialized)
    usage_error(impl_->name, "declare_checkpointable() comes before initialize()");
  impl_->checkpointable = true;
}

void Participant::declare_restartable_on_other_ranks() {
  if (impl_->initialized)
    usage_error(impl_->name, "declare_restartable_on_other_ranks() comes before initialize()");
  impl_->restartable_on_other_ranks = true;
}

const std::filesystem::path& Participant::restart_directory() const {
  return impl_->restart_directory.empty() ? impl_->endpoint.restart : impl_->restart_directory;
}

const std::vector<std::filesystem::path>& Participant::restart_parts() const {
  return impl_->restart_parts;
}

bool Participant::restarts_on_other_ranks() const {
  return !impl_->restart_parts.empty() &&
         impl_->restart_parts.size() != static_cast<std::size_t>(impl_->parts);
}

void Participant::set_standalone_window(double window) {
  if (!(window > 0.0)) usage_error(impl_->name, "the standalone window must be positive");
  impl_->standalone_window = window;
}

void Participant::initialize(double start_time, double end_time) {
  Impl& s = *impl_;
  if (s.initialized) usage_error(s.name, "initialize() called twice");
  if (!(end_time >= start_time))
    usage_error(s.name, fmt::format("end time {} is before start time {}", end_time, start_time));
  s.initialized = true;
  s.window = 1;
  const bool restarts = !s.endpoint.restart.empty();
  if (restarts && !s.checkpointable)
    usage_error(s.name, "--cosim-restart needs a solver that declares it is checkpointable");
  if (restarts && !is_coupled())
    usage_error(s.name, "--cosim-restart is for participants started by `cosim run --restart`");
  if (!is_coupled()) {
    s.schedule.start_time = start_time;
    s.schedule.end_time = end_time;
    s.schedule.window =
        s.standalone_window > 0.0 ? s.standalone_window : std::max(end_time - start_time, 1e-300);
    s.time = start_time;
    if (s.endpoint.repeat_windows && !s.repeatable)
      usage_error(s.name, "--cosim-repeat-windows needs a solver that declares it is repeatable");
    s.save_state = s.repeats_windows();
    return;
  }

  const std::string& uri = s.endpoint.uri;
  if (uri.rfind("mpi://", 0) == 0)
    s.transport = std::make_unique<com::MpiClient>(s.name);
  else
    s.transport = std::make_unique<com::ZmqClient>(uri, s.name);
  const bool partitioned = s.find_part();

  com::Hello hello;
  hello.participant = s.name;
  hello.config_hash = s.endpoint.config_hash;
  hello.token = s.endpoint.token;
  hello.pid = static_cast<long>(::getpid());
  hello.program = "cosim participant " COSIM_VERSION;
  for (const auto& [mesh_name, entry] : s.meshes)
    hello.meshes.push_back({mesh_name, entry.mesh.kind(), entry.mesh.dimension()});
  for (const auto& [field_name, w] : s.writes) hello.writes.push_back(w.spec);
  for (const auto& [field_name, r] : s.reads) hello.reads.push_back(r.spec);
  hello.repeatable = s.repeatable;
  hello.checkpointable = s.checkpointable;
  hello.part = s.part;
  hello.parts = s.parts;
  hello.partitioned = partitioned;
  std::size_t restart_window = 0;
  if (restarts) restart_window = s.restore_from_checkpoint();
  hello.restart_window = restart_window;
  const double restart_time = s.time;
  s.window = 0;
  s.send(com::make_text_message(MessageType::hello, s.endpoint.job_id, s.name, 0, start_time,
                                com::to_json(hello)));
  com::Message reply = s.receive(s.endpoint.connect_timeout_s);
  if (reply.header.type != MessageType::welcome)
    throw ProtocolError(com::coupler_peer,
                        fmt::format("answered hello with '{}'", com::to_string(reply.header.type)));
  s.schedule = com::parse_welcome(reply.payload.text(), com::coupler_peer);
  if (s.schedule.config_hash != s.endpoint.config_hash)
    throw ProtocolError(com::coupler_peer,
                        fmt::format("runs a job config with hash {}, participant '{}' was started "
                                    "for hash {}",
                                    s.schedule.config_hash, s.name, s.endpoint.config_hash));
  s.admitted = true;
  if (std::abs(s.schedule.end_time - end_time) > 0.0 || s.schedule.start_time != start_time)
    spdlog::info(
        "participant '{}': the job's schedule [{}, {}] s replaces the solver's own [{}, "
        "{}] s",
        s.name, s.schedule.start_time, s.schedule.end_time, start_time, end_time);
  if (restarts) {
    // The fields received at the checkpoint's window end are those read now.
    s.window = restart_window + 1;
    s.time = s.window_start();
    if (s.time != restart_time)
      throw Error(ExitCode::bad_input,
                  fmt::format("{}: the checkpoint is at t = {:.17g} s, the job's window {} ends at "
                              "t = {:.17g} s",
                              s.endpoint.restart.string(), restart_time, restart_window, s.time));
    s.save_state = s.repeats_windows() && is_coupling_ongoing();
    return;
  }
  s.time = s.schedule.start_time;
  for (auto& [field_name, r] : s.reads) r.received_at = r.previous_at = s.time;

  // Window 0 carries the initial data both ways.
  s.send_window_data();
  s.receive_window_data();
  s.window = 1;
  s.timings.windows = 0;
  s.save_state = s.repeats_windows() && is_coupling_ongoing();
}

double Participant::time() const {
  return impl_->time;
}
double Participant::window_size() const {
  return impl_->schedule.window;
}
std::size_t Participant::window_index() const {
  return impl_->window;
}
std::size_t Participant::iteration() const {
  return impl_->iteration;
}
double Participant::end_time() const {
  return impl_->schedule.end_time;
}

double Participant::max_time_step() const {
  return impl_->window_end() - impl_->time;
}

bool Participant::is_coupling_ongoing() const {
  const Impl& s = *impl_;
  if (!s.initialized || s.finished || s.finalized) return false;
  return s.time < s.schedule.end_time - window_end_tolerance * s.schedule.window;
}

void Participant::update_mesh(const Mesh& mesh) {
  auto it = impl_->meshes.find(mesh.name);
  if (it == impl_->meshes.end())
    usage_error(impl_->name, fmt::format("updates undeclared mesh '{}'", mesh.name));
  if (mesh.kind() != it->second.mesh.kind() || mesh.size() != it->second.mesh.size())
    usage_error(impl_->name,
                fmt::format("mesh '{}' may move but not change kind or size", mesh.name));
  validate(mesh);
  it->second.mesh = mesh;
  it->second.changed = true;
}

void Participant::update_mesh(const Mesh& mesh, MeshPart part) {
  Impl& s = *impl_;
  auto it = s.meshes.find(mesh.name);
  if (it == s.meshes.end() || !it->second.part)
    usage_error(s.name,
                fmt::format("updates mesh '{}', which is not declared with a part", mesh.name));
  if (mesh.kind() != it->second.mesh.kind())
    usage_error(s.name, fmt::format("mesh '{}' may move but not change kind", mesh.name));
  validate(mesh);
  check_part(s.name, mesh, part);
  const std::size_t n = part.size();
  if (n != it->second.values()) {
    for (auto& [field_name, w] : s.writes) {
      if (w.spec.mesh != mesh.name) continue;
      if (w.spec.time == TimeTreatment::integral && s.time > s.window_start())
        usage_error(s.name, fmt::format("the part of mesh '{}' changed size within a window, "
                                        "while integral field '{}' accumulates on it",
                                        mesh.name, field_name));
      const std::size_t size = n * static_cast<std::size_t>(w.spec.components);
      w.values.assign(size, 0.0);
      w.integral.assign(size, 0.0);
    }
    for (auto& [field_name, r] : s.reads) {
      if (r.spec.mesh != mesh.name) continue;
      const std::size_t size = n * static_cast<std::size_t>(r.spec.components);
      for (auto* buffer : {&r.current, &r.previous, &r.start, &r.delivered})
        buffer->assign(size, 0.0);
      r.has_previous = false;
    }
  }
  it->second.mesh = mesh;
  it->second.part = std::move(part);
  it->second.changed = true;
}

void Participant::write(std::string_view field, std::span<const double> values) {
  auto it = impl_->writes.find(field);
  if (it == impl_->writes.end())
    usage_error(impl_->name, fmt::format("writes undeclared field '{}'", field));
  WriteBuffer& w = it->second;
  if (values.size() != w.values.size())
    usage_error(impl_->name, fmt::format("wrote {} values to field '{}', which has {}",
                                         values.size(), field, w.values.size()));
  std::copy(values.begin(), values.end(), w.values.begin());
  w.written = true;
}

void Participant::advance(double dt) {
  Impl& s = *impl_;
  if (!s.initialized) usage_error(s.name, "advance() before initialize()");
  if (!is_coupling_ongoing()) usage_error(s.name, "advance() after the end of the coupling");
  if (s.write_checkpoint)
    usage_error(s.name, "advance() before checkpoint_written(): the coupler waits for it");
  runtime::throw_if_stop_requested();
  const double remaining = s.window_end() - s.time;
  const double tolerance = window_end_tolerance * s.schedule.window;
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw NumericalError(fmt::format("participant '{}': time step {} is not positive", s.name, dt));
  if (dt > remaining + tolerance)
    usage_error(s.name, fmt::format("step {} s overshoots the window end by {} s (use "
                                    "max_time_step())",
                                    dt, dt - remaining));
  for (auto& [field_name, w] : s.writes)
    if (w.spec.time == TimeTreatment::integral)
      for (std::size_t i = 0; i < w.values.size(); ++i) w.integral[i] += w.values[i] * dt;

  const bool completes_window = dt >= remaining - tolerance;
  s.time = completes_window ? s.window_end() : s.time + dt;
  s.save_state = s.restore_state = s.window_complete = false;
  if (!completes_window) return;

  ++s.timings.iterations;
  if (is_coupled()) {
    s.send_window_data();
    s.receive_window_data();
  } else {
    // Standalone check of save and restore: the first attempt is repeated.
    s.repeat_requested = s.endpoint.repeat_windows && s.iteration == 1;
  }
  for (auto& [field_name, r] : s.reads) std::fill(r.delivered.begin(), r.delivered.end(), 0.0);
  if (s.repeat_requested) {
    s.time = s.window_start();
    ++s.iteration;
    s.restore_state = true;
    return;
  }
  ++s.timings.windows;
  ++s.window;
  s.iteration = 1;
  s.window_complete = true;
  s.save_state = s.repeats_windows() && is_coupling_ongoing();
  s.write_checkpoint = !s.finished && !s.checkpoint_directory.empty();
}

bool Participant::must_save_state() const {
  return impl_->save_state;
}
bool Participant::must_restore_state() const {
  return impl_->restore_state;
}
bool Participant::reads_vary_within_window() const {
  return impl_->schedule.time_interpolation == com::TimeInterpolation::linear;
}
bool Participant::is_window_complete() const {
  return impl_->window_complete;
}
bool Participant::must_write_checkpoint() const {
  return impl_->write_checkpoint;
}
const std::filesystem::path& Participant::checkpoint_directory() const {
  return impl_->checkpoint_directory;
}

void Participant::checkpoint_written() {
  Impl& s = *impl_;
  if (!s.write_checkpoint) usage_error(s.name, "checkpoint_written() without a checkpoint due");
  s.write_state(s.checkpoint_directory);
  s.write_checkpoint = false;
  s.checkpoint_directory.clear();
  s.send(s.header_only(MessageType::checkpoint_done));
  // The run stops here; a restart from the checkpoint continues it.
  if (s.stop_after_checkpoint) {
    s.finished = true;
    s.save_state = false;
  }
}

void Participant::read(std::string_view field, std::span<double> values,
                       double relative_time) const {
  const Impl& s = *impl_;
  const ReadBuffer& r = s.read_buffer(field);
  if (values.size() != r.current.size())
    usage_error(s.name, fmt::format("reads {} values of field '{}', which has {}", values.size(),
                                    field, r.current.size()));
  if (!(relative_time >= 0.0) ||
      relative_time > max_time_step() + window_end_tolerance * s.schedule.window)
    usage_error(s.name,
                fmt::format("reads '{}' {} s ahead, outside the window", field, relative_time));
  const double t = s.time + relative_time;
  const bool holds_window_end =
      r.received_at > s.window_start() + window_end_tolerance * s.schedule.window;
  if (holds_window_end && r.spec.time == TimeTreatment::state &&
      s.schedule.time_interpolation == com::TimeInterpolation::linear) {
    // Waveform relaxation: linear in time between the window's two ends.
    const double share = (t - s.window_start()) / (s.window_end() - s.window_start());
    for (std::size_t i = 0; i < values.size(); ++i)
      values[i] = r.start[i] + share * (r.current[i] - r.start[i]);
    return;
  }
  const bool extrapolate = !s.schedule.implicit &&
                           s.schedule.extrapolation == com::Extrapolation::linear &&
                           r.has_previous && r.received_at > r.previous_at;
  if (!extrapolate) {
    std::copy(r.current.begin(), r.current.end(), values.begin());
    return;
  }
  const double slope_factor = (t - r.received_at) / (r.received_at - r.previous_at);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = r.current[i] + slope_factor * (r.current[i] - r.previous[i]);
}

std::vector<double> Participant::read(std::string_view field) const {
  std::vector<double> values(impl_->read_buffer(field).current.size());
  read(field, values);
  return values;
}

void Participant::read_increment(std::string_view field, double dt, std::span<double> values) {
  Impl& s = *impl_;
  auto it = s.reads.find(field);
  if (it == s.reads.end() || it->second.spec.time != TimeTreatment::integral)
    usage_error(s.name,
                fmt::format("read_increment() needs a declared integral field, not '{}'", field));
  ReadBuffer& r = it->second;
  if (values.size() != r.current.size())
    usage_error(s.name, fmt::format("reads {} values of field '{}', which has {}", values.size(),
                                    field, r.current.size()));
  const double remaining = s.window_end() - s.time;
  const bool last_step = dt >= remaining - window_end_tolerance * s.schedule.window;
  const double share = std::min(1.0, dt / s.schedule.window);
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = last_step ? r.current[i] - r.delivered[i] : r.current[i] * share;
    r.delivered[i] += values[i];
  }
}

bool Participant::is_sent(std::string_view field) const {
  (void)impl_->read_buffer(field);  // a field it does not read is a usage error
  const auto& sends = impl_->schedule.sends;
  return impl_->admitted && std::find(sends.begin(), sends.end(), field) != sends.end();
}

std::size_t Participant::field_size(std::string_view field) const {
  if (auto w = impl_->writes.find(field); w != impl_->writes.end()) return w->second.values.size();
  return impl_->read_buffer(field).current.size();
}

const CouplingTimings& Participant::timings() const {
  return impl_->timings;
}

void Participant::finalize() {
  Impl& s = *impl_;
  if (s.finalized) return;
  s.finalized = true;
  if (s.transport && s.admitted && !s.finished) {
    // Leaving before the coupler said the run is over: tell it why.
    s.send(com::make_text_message(MessageType::abort, s.endpoint.job_id, s.name, s.window, s.time,
                                  "participant finalized before the end of the coupling"));
  }
  s.transport.reset();
}

void Participant::abort(std::string_view reason) {
  Impl& s = *impl_;
  if (s.finalized) return;
  s.finalized = true;
  if (s.transport && s.admitted && !s.finished) {
    try {
      s.send(s.abort_message(reason));
    } catch (...) {
    }
  }
  s.transport.reset();
}

}  // namespace cosim

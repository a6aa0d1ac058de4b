#include "cplscheme/coupler.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <thread>

#include "admission.hpp"
#include "checkpoint/manifest.hpp"
#include "checkpoint/mesh_state.hpp"
#include "checkpoint/store.hpp"
#include "com/handshake.hpp"
#include "cosim/error.hpp"
#include "cosim/fields.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/tail_lines.hpp"
#include "energy_exchange_step.hpp"
#include "fields_by_peer.hpp"
#include "mapping/bounded_redistribution.hpp"
#include "mapping/build_operator.hpp"
#include "momentum_exchange_step.hpp"
#include "operator_cache.hpp"
#include "progress.hpp"
#include "window_iteration.hpp"

namespace cosim::cplscheme {

using com::MessageType;
using Clock = std::chrono::steady_clock;

namespace {

constexpr auto poll_slice = std::chrono::milliseconds(50);
// Window ends reported by participants agree with the coupler's to this
// fraction of a window.
constexpr double time_tolerance = 1e-9;
// The coupler's own part of a checkpoint (architecture.md §14).
constexpr const char* coupler_state_file = "coupler.h5";
constexpr const char* coupler_state_kind = "cosim_coupler";
constexpr std::int64_t coupler_state_version = 1;

struct Peer {
  const job::ParticipantSpec* spec = nullptr;
  bool connected = false;
  com::Hello hello;
  std::map<std::string, Mesh> meshes;
  std::map<std::string, std::size_t> mesh_version;
  std::map<std::string, std::vector<double>> written;
  bool window_done = false;
};

double sum(std::span<const double> v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

double abs_sum(std::span<const double> v) {
  double s = 0.0;
  for (double x : v) s += std::abs(x);
  return s;
}

// Connections that are not participants (a stranger on the endpoint, a
// process of another run) are logged, not obeyed; the first few in full,
// then one line in a thousand, so a flood cannot fill the log.
class StrangerLog {
 public:
  void dropped(const std::string& connection, const std::string& what) {
    if (worth_a_line(++dropped_))
      spdlog::warn("ignored {} from {}, which is not a participant of this run ({} so far)", what,
                   connection, dropped_);
  }
  void refused(const std::string& connection, const std::string& reason) {
    if (worth_a_line(++refused_))
      spdlog::warn("refused '{}': {} ({} refusals so far)", connection, reason, refused_);
  }

 private:
  static bool worth_a_line(std::size_t n) { return n <= 10 || n % 1000 == 0; }
  std::size_t dropped_ = 0;
  std::size_t refused_ = 0;
};

bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
  return difference == 0;
}

}  // namespace

struct Coupler::Impl {
  const job::Job& job;
  com::Hub& transport;
  runtime::Supervisor* supervisor;
  RunSummary& summary;
  CouplerOptions options;
  std::map<std::string, Peer> peers;
  OperatorCache operators;
  std::optional<MomentumExchangeStep> momentum_exchange;
  double max_momentum_balance_error = 0.0;
  std::optional<EnergyExchangeStep> energy_exchange;
  double max_energy_balance_error = 0.0;
  std::map<std::string, std::unique_ptr<SnapshotWriter>> snapshot_writers;
  std::size_t window = 0;
  double max_conservation_error = 0.0;
  double next_output_time = 0.0;
  StrangerLog strangers;
  std::optional<WindowIteration> iteration;  // implicit schemes
  // Implicit schemes: the momentum per exchange cell in the fields last sent
  // (the iterate the participants run), and in the last answer.
  ExchangeCellImpulses applied_exchange_impulses, answered_exchange_impulses;
  ExchangeCellHeat applied_exchange_heat, answered_exchange_heat;
  std::optional<checkpoint::Store> checkpoints;
  std::size_t checkpoints_written = 0;
  bool stop_at_next_window = false;  // asked to stop (SIGTERM) while checkpointing
  bool stopped_at_checkpoint = false;
  // Participants' messages of the next window that arrived while the coupler
  // waited for a checkpoint: handled first when that window is collected.
  std::deque<com::Received> deferred;

  Impl(const job::Job& j, com::Hub& t, runtime::Supervisor* s, RunSummary& sum, CouplerOptions o)
      : job(j), transport(t), supervisor(s), summary(sum), options(std::move(o)) {
    if (options.checkpoint_every) checkpoints.emplace(options.output_dir, options.checkpoints_kept);
    for (const auto& p : job.participants) peers[p.name].spec = &p;
    if (job.momentum_exchange) momentum_exchange.emplace(*job.momentum_exchange, job.file.string());
    if (job.energy_exchange) energy_exchange.emplace(*job.energy_exchange, job.file.string());
  }

  double window_time(std::size_t w) const {
    return std::min(job.end_time, job.start_time + static_cast<double>(w) * job.window);
  }

  // Fails the run when a participant process ended before the coupler said
  // the run is over.
  void check_processes() {
    if (options.interrupted && options.interrupted->load()) {
      // A checkpointing run stops at its next window end, with a checkpoint.
      if (!options.checkpoint_every)
        throw Error(ExitCode::participant_failed, "interrupted by a signal; participants stopped");
      if (!stop_at_next_window)
        spdlog::warn("asked to stop: a checkpoint at the end of window {}, then the run stops",
                     window);
      stop_at_next_window = true;
    }
    if (!supervisor) return;
    for (const runtime::ChildExit& e : supervisor->reap())
      throw Error(e.coupled_exit_code(),
                  fmt::format("participant '{}' (pid {}) {} during window {}{}", e.name, e.pid,
                              e.describe(), window, last_lines_of(e.name)));
  }

  std::string last_lines_of(const std::string& name) const {
    if (!supervisor) return {};
    const auto lines = tail_lines(supervisor->log_file(name), 15);
    if (lines.empty()) return {};
    std::string out =
        fmt::format("\n--- last lines of {} ---", supervisor->log_file(name).string());
    for (const auto& l : lines) out += "\n  " + l;
    return out;
  }

  void send(const std::string& peer, const com::Message& m) {
    auto scope = summary.phases().measure("transport");
    try {
      transport.send(peer, m);
    } catch (const ProtocolError&) {
      // A peer that cannot be reached has usually died: its exit status is
      // the better report. The kernel closes a dying process's socket a
      // moment before the process can be reaped, so give it that moment.
      for (int i = 0; i < 50; ++i) {
        check_processes();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      throw;
    }
  }

  com::Message message(MessageType type, double time) const {
    com::Message m;
    m.header.type = type;
    m.header.job_id = options.job_id;
    m.header.sender = com::coupler_peer;
    m.header.window = window;
    m.header.time = time;
    return m;
  }

  // One message, or nothing within a poll slice; participants' deaths and
  // the deadline are checked between slices.
  std::optional<com::Received> receive(Clock::time_point deadline, const std::string& waiting_for,
                                       bool take_deferred = true) {
    if (take_deferred && !deferred.empty()) {
      com::Received r = std::move(deferred.front());
      deferred.pop_front();
      return r;
    }
    for (;;) {
      check_processes();
      std::optional<com::Received> r;
      {
        auto scope = summary.phases().measure("waiting");
        r = transport.receive(poll_slice);
      }
      if (r) return r;
      if (Clock::now() >= deadline)
        throw Error(ExitCode::participant_failed,
                    fmt::format("timed out waiting for {} (hung participant?)", waiting_for));
    }
  }

  // Tells a connection that is not admitted why; one that is gone already
  // costs nothing (no wait for a participant's death, as send() does).
  void refuse(const std::string& peer, const std::string& reason) {
    strangers.refused(peer, reason);
    try {
      transport.send(peer, com::make_text_message(MessageType::refuse, options.job_id,
                                                  com::coupler_peer, 0, 0.0, reason));
    } catch (const std::exception&) {
    }
  }

  // A hello from a connection not yet admitted: the participant it names is
  // admitted when its run token, job, config and declarations check out.
  void consider_hello(const com::Received& r, std::size_t& connected) {
    const com::Header& h = r.message.header;
    com::Hello hello;
    try {
      com::validate_payload(r.message, r.peer, false);
      hello = com::parse_hello(r.message.payload.text(), r.peer);
    } catch (const ProtocolError& e) {
      refuse(r.peer, e.what());
      return;
    }
    if (!options.tokens.empty()) {
      auto token = options.tokens.find(h.sender);
      if (token == options.tokens.end() || !same_secret(hello.token, token->second)) {
        strangers.dropped(r.peer, fmt::format("a hello as '{}' without its run token", h.sender));
        refuse(r.peer, "not admitted: this run admits only the processes it started");
        return;
      }
    }
    if (auto reason = admission_refusal(job, options.job_id, h, hello)) {
      refuse(r.peer, *reason);
      return;
    }
    Peer& peer = peers.at(h.sender);
    const bool whole_on_ranks = hello.parts > 1 && !hello.partitioned;
    if (hello.parts != peer.spec->ranks || whole_on_ranks) {
      const std::string what =
          whole_on_ranks
              ? fmt::format(
                    "participant '{}' ({}) runs on {} ranks, but its program declares its "
                    "meshes whole: it does not run on several ranks in a coupled job; "
                    "give it `ranks: 1`",
                    h.sender, hello.program, hello.parts)
              : fmt::format("participant '{}' ({}) runs on {} rank{}, the job gives it {}",
                            h.sender, hello.program, hello.parts, hello.parts == 1 ? "" : "s",
                            peer.spec->ranks);
      refuse(r.peer, what);
      if (peer.spec->ranks_where.line > 0)
        throw InputError(peer.spec->ranks_where, fmt::format("participants.{}.ranks", h.sender),
                         what);
      throw InputError(what);
    }
    if (peer.connected) {
      refuse(r.peer, fmt::format("participant '{}' is already connected", h.sender));
      return;
    }
    try {
      transport.admit(r.peer, h.sender);
    } catch (const ProtocolError& e) {
      refuse(r.peer, e.what());
      return;
    }
    peer.connected = true;
    peer.hello = hello;
    ++connected;
    if (job.coupling.is_implicit() && !hello.repeatable)
      throw InputError(
          job.coupling.scheme_where, "coupling.scheme",
          fmt::format("participant '{}' ({}) cannot repeat a window (it does not save and restore "
                      "its state), which the implicit scheme needs; use scheme: "
                      "parallel-explicit",
                      h.sender, hello.program));
    const bool checkpointing = options.checkpoint_every || !options.restart.empty();
    if (checkpointing && !hello.checkpointable)
      throw InputError(fmt::format(
          "participant '{}' ({}) cannot write its state into a checkpoint or start from one; "
          "run the job without --checkpoint-every and --restart",
          h.sender, hello.program));
    if (hello.restart_window != options.restart_window)
      throw InputError(fmt::format(
          "participant '{}' started from window {}, the coupler from "
          "window {} of {}",
          h.sender, hello.restart_window, options.restart_window, options.restart.string()));
    spdlog::info("participant '{}' connected ({}, pid {})", h.sender, hello.program, hello.pid);
  }

  std::string not_connected() const {
    std::string names;
    for (const auto& [name, peer] : peers)
      if (!peer.connected) names += (names.empty() ? "'" : ", '") + name + "'";
    return names;
  }

  void admit_participants() {
    const auto deadline = Clock::now() + std::chrono::milliseconds(
                                             static_cast<long>(options.connect_timeout_s * 1e3));
    std::size_t connected = 0;
    while (connected < peers.size()) {
      const std::optional<com::Received> r = receive(
          deadline,
          fmt::format("{} to connect ({} of {} did)", not_connected(), connected, peers.size()));
      if (r->malformed) {
        // A peer speaking another protocol version or garbage: say why, and
        // keep waiting for the real participants.
        strangers.dropped(r->peer, "a malformed message");
        refuse(r->peer, *r->malformed);
        continue;
      }
      const com::Header& h = r->message.header;
      if (r->admitted) {
        check_signature(r->peer, h);
        if (h.type == MessageType::abort) throw participant_abort(r->peer, r->message);
        throw ProtocolError(r->peer, fmt::format("sent '{}' before every participant had connected",
                                                 com::to_string(h.type)));
      }
      if (h.type == MessageType::abort) continue;  // a refused peer saying goodbye
      if (h.type != MessageType::hello) {
        strangers.dropped(r->peer, fmt::format("a '{}' message", com::to_string(h.type)));
        continue;
      }
      consider_hello(*r, connected);
    }
    check_exchange_declarations();
    com::Welcome welcome;
    welcome.config_hash = job.config_hash;
    welcome.start_time = job.start_time;
    welcome.end_time = job.end_time;
    welcome.window = job.window;
    welcome.extrapolation = job.extrapolation;
    welcome.implicit = job.coupling.is_implicit();
    welcome.time_interpolation = job.coupling.time_interpolation;
    // The coupler judges which participant hangs; the others wait longer
    // than it does so that they do not time out first and take the blame.
    welcome.timeout_s = 2.0 * job.window_timeout_s + 10.0;
    for (const auto& [name, peer] : peers) {
      welcome.sends.clear();
      for (const auto& [field, mesh] : job.participant(name)->reads) welcome.sends.push_back(field);
      send(name, com::make_text_message(MessageType::welcome, options.job_id, com::coupler_peer, 0,
                                        job.start_time, com::to_json(welcome)));
    }
  }

  static const FieldSpec& declared(const std::vector<FieldSpec>& fields, const std::string& name) {
    return *std::find_if(fields.begin(), fields.end(), [&](auto& f) { return f.name == name; });
  }

  void check_exchange_declarations() {
    for (const job::ExchangeSpec& x : job.exchanges) {
      const FieldSpec& w = declared(peers.at(x.from).hello.writes, x.field);
      const FieldSpec& r = declared(peers.at(x.to).hello.reads, x.field);
      if (auto mismatch = exchange_mismatch(x, w, r))
        throw InputError(SourceLocation{job.file.string(), x.where.line, x.where.column},
                         x.key_path, *mismatch);
    }
    if (momentum_exchange)
      momentum_exchange->check_declarations(job, peers.at(job.momentum_exchange->fluid).hello,
                                            peers.at(job.momentum_exchange->solid).hello);
    if (energy_exchange)
      energy_exchange->check_declarations(job, peers.at(job.energy_exchange->fluid).hello,
                                          peers.at(job.energy_exchange->solid).hello);
  }

  // Every message of an admitted participant names this job and the
  // participant itself.
  void check_signature(const std::string& name, const com::Header& h) const {
    if (h.job_id != options.job_id)
      throw ProtocolError(name, fmt::format("sent a '{}' message for job '{}' in job '{}'",
                                            com::to_string(h.type), h.job_id, options.job_id));
    if (h.sender != name)
      throw ProtocolError(
          name, fmt::format("sent a '{}' message signed '{}'", com::to_string(h.type), h.sender));
  }

  // A participant that reports its own failure is given a moment to finish
  // its record (summary.json, the last lines of its log) and exit; its exit
  // status then says what failed (a numerical failure passes through as
  // cosim's exit 4). Without a supervisor (MPI) the code it declared does.
  Error participant_abort(const std::string& name, const com::Message& m) {
    ExitCode code = exit_code_from_string(m.header.field);
    if (code != ExitCode::bad_input && code != ExitCode::numerical_failure)
      code = ExitCode::participant_failed;
    std::string how = "aborted";
    if (supervisor) {
      if (auto exit = supervisor->wait_for(name, options.failure_grace)) {
        code = exit->coupled_exit_code();
        how = "aborted and " + exit->describe();
      }
    }
    return Error(code, fmt::format("participant '{}' {} in window {}: {}{}", name, how, window,
                                   m.payload.text(), last_lines_of(name)));
  }

  void handle_window_message(const std::string& name, const com::Message& m) {
    Peer& peer = peers.at(name);
    const com::Header& h = m.header;
    check_signature(name, h);
    if (h.type == MessageType::abort) throw participant_abort(name, m);
    if (h.window != window)
      throw ProtocolError(name, fmt::format("sent a '{}' message for window {} during window {}",
                                            com::to_string(h.type), h.window, window));
    switch (h.type) {
      case MessageType::mesh: {
        Mesh mesh = com::decode_mesh_message(m, name);
        auto declared_mesh = std::find_if(peer.hello.meshes.begin(), peer.hello.meshes.end(),
                                          [&](auto& d) { return d.name == mesh.name; });
        if (declared_mesh == peer.hello.meshes.end() || declared_mesh->kind != mesh.kind() ||
            declared_mesh->dim != mesh.dimension())
          throw ProtocolError(
              name, fmt::format("sent mesh '{}' ({}D {}) that it did not declare", mesh.name,
                                mesh.dimension(), to_string(mesh.kind())));
        auto old = peer.meshes.find(mesh.name);
        if (old != peer.meshes.end() && old->second.size() != mesh.size())
          throw ProtocolError(name, fmt::format("mesh '{}' changed size from {} to {}", mesh.name,
                                                old->second.size(), mesh.size()));
        peer.meshes[mesh.name] = std::move(mesh);
        ++peer.mesh_version[h.mesh];
        return;
      }
      case MessageType::field: {
        auto spec = std::find_if(peer.hello.writes.begin(), peer.hello.writes.end(),
                                 [&](auto& f) { return f.name == h.field; });
        if (spec == peer.hello.writes.end())
          throw ProtocolError(name,
                              fmt::format("sent field '{}' that it did not declare", h.field));
        auto mesh = peer.meshes.find(spec->mesh);
        if (h.mesh != spec->mesh || mesh == peer.meshes.end())
          throw ProtocolError(
              name, fmt::format("sent field '{}' on mesh '{}' before that mesh", h.field, h.mesh));
        if (h.count != mesh->second.size() ||
            h.components != static_cast<std::uint32_t>(spec->components))
          throw ProtocolError(name, fmt::format("field '{}' has {} x {} values, mesh '{}' needs "
                                                "{} x {}",
                                                h.field, h.count, h.components, h.mesh,
                                                mesh->second.size(), spec->components));
        com::validate_payload(m, name, spec->allow_nonfinite);
        peer.written[h.field] = m.payload.doubles();
        return;
      }
      case MessageType::window_end: {
        const double expected = window_time(window);
        if (std::abs(h.time - expected) > time_tolerance * job.window)
          throw ProtocolError(name, fmt::format("ended window {} at t = {:.17g} s, the coupler's "
                                                "window ends at t = {:.17g} s",
                                                window, h.time, expected));
        for (const FieldSpec& f : peer.hello.writes)
          if (!peer.written.count(f.name))
            throw ProtocolError(
                name, fmt::format("ended window {} without sending '{}'", window, f.name));
        peer.window_done = true;
        return;
      }
      default:
        throw ProtocolError(name, fmt::format("unexpected '{}' message during window {}",
                                              com::to_string(h.type), window));
    }
  }

  // A message during the run from a connection that is not a participant.
  void drop_stranger(const com::Received& r) {
    if (r.malformed) {
      strangers.dropped(r.peer, "a malformed message");
    } else if (r.message.header.type == MessageType::hello) {
      strangers.dropped(r.peer, fmt::format("a late hello as '{}'", r.message.header.sender));
      refuse(r.peer, "the run has started; late or unknown participants are refused");
    } else {
      strangers.dropped(r.peer,
                        fmt::format("a '{}' message", com::to_string(r.message.header.type)));
    }
  }

  // Every participant's end of the window, or (serial schemes) one's.
  void collect_window(const std::string* only = nullptr) {
    auto expected = [&](const std::string& name) { return !only || name == *only; };
    for (auto& [name, peer] : peers) peer.window_done = false;
    const auto deadline =
        Clock::now() + std::chrono::milliseconds(static_cast<long>(job.window_timeout_s * 1e3));
    auto pending = [&] {
      std::string names;
      for (const auto& [name, peer] : peers)
        if (expected(name) && !peer.window_done)
          names += (names.empty() ? "'" : ", '") + name + "'";
      return names;
    };
    const std::size_t awaited = only ? 1 : peers.size();
    std::size_t done = 0;
    while (done < awaited) {
      auto r = receive(deadline, fmt::format("window {} from {} (window_timeout {} s)", window,
                                             pending(), job.window_timeout_s));
      if (!r->admitted) {
        drop_stranger(*r);
        continue;
      }
      const bool was_done = peers.at(r->peer).window_done;
      handle_window_message(r->peer, r->message);
      if (!was_done && peers.at(r->peer).window_done) {
        if (!expected(r->peer))
          throw ProtocolError(r->peer, fmt::format("ended window {} out of turn (serial scheme: "
                                                   "'{}' runs it now)",
                                                   window, *only));
        ++done;
      }
    }
  }

  const mapping::Operator& operator_for(std::size_t index) {
    const job::ExchangeSpec& x = job.exchanges[index];
    Peer& from = peers.at(x.from);
    Peer& to = peers.at(x.to);
    const std::string& source_mesh = from.spec->writes.at(x.field);
    const std::string& target_mesh = to.spec->reads.at(x.field);
    const OperatorKey key{
        {x.from, source_mesh}, {x.to, target_mesh}, x.mapping.constraint, x.mapping.kernel};
    return operators.get(key, from.meshes.at(source_mesh), from.mesh_version[source_mesh],
                         to.meshes.at(target_mesh), to.mesh_version[target_mesh]);
  }

  PhaseSide side_of(const std::string& name) {
    Peer& p = peers.at(name);
    return {p.spec, &p.hello, &p.meshes, &p.mesh_version, &p.written};
  }

  // An explicit exchange of porosity and pore pressure is stable only when
  // the window resolves the pore fluid's undrained wave across an exchange
  // cell (architecture.md §3). Window 0 carries every initial field: the bound is
  // known before anything is integrated, and a window far above it is
  // refused then.
  void check_explicit_stability() {
    if (!momentum_exchange) return;
    const job::MomentumExchangeSpec& spec = *job.momentum_exchange;
    const auto bound = momentum_exchange->explicit_window_bound(side_of(spec.fluid),
                                                                side_of(spec.solid), operators);
    if (!bound || !bound->applies()) return;
    const double ratio = job.window / bound->window;
    const Vec3 at = peers.at(spec.mesh_owner).meshes.at(spec.mesh).position(bound->cell);
    summary.set_metric("explicit_window_bound", bound->window, "s");
    summary.set_section("stability", {{"window_s", job.window},
                                      {"bound_s", bound->window},
                                      {"window_over_bound", ratio},
                                      {"wave_speed_m_per_s", bound->wave_speed},
                                      {"cell_width_m", bound->cell_width},
                                      {"porosity", bound->porosity},
                                      {"cell", bound->cell},
                                      {"refuse_above", job.stability.refuse_above},
                                      {"accept_unstable", job.stability.accept_unstable}});
    if (job.coupling.is_implicit()) {
      spdlog::info(
          "implicit coupling: the window {} s is {:.3g} times the explicit scheme's "
          "stability bound {:.3g} s",
          job.window, ratio, bound->window);
      return;
    }
    if (ratio <= 1.0) {
      spdlog::info("explicit coupling: the window {} s is {:.2g} of its stability bound {:.3g} s",
                   job.window, ratio, bound->window);
      return;
    }
    const std::string what = fmt::format(
        "the window {} s is {:.3g} times the explicit coupling's stability bound {:.3g} s: the "
        "pore "
        "fluid's undrained pressure wave ({:.4g} m/s at porosity {:.3g}) crosses an exchange "
        "cell of {:.3g} m in that time (at ({:.4g}, {:.4g}, {:.4g}) m of {}.{}), and an explicit "
        "exchange of porosity and pore pressure over a longer window grows without bound "
        "(architecture.md §3); use a window <= {:.2g} s",
        job.window, ratio, bound->window, bound->wave_speed, bound->porosity, bound->cell_width,
        at[0], at[1], at[2], spec.mesh_owner, spec.mesh, bound->window);
    if (ratio > job.stability.refuse_above && !job.stability.accept_unstable)
      throw InputError(
          job.window_where.file.empty()
              ? SourceLocation{job.file.string(), job.window_where.line, job.window_where.column}
              : job.window_where,
          "window",
          what + fmt::format(" (a window above {} times the bound is refused; "
                             "`stability_check: {{accept_unstable: true}}` runs it "
                             "anyway)",
                             job.stability.refuse_above));
    spdlog::warn("explicit coupling: {}", what);
  }

  void exchange_momentum(FieldsByPeer& out) {
    if (!momentum_exchange) return;
    auto scope = summary.phases().measure("exchange");
    const job::MomentumExchangeSpec& spec = *job.momentum_exchange;
    // Window 0 carries the initial state: nothing has been integrated yet.
    const double dt = window == 0 ? 0.0 : job.window;
    auto impulses =
        momentum_exchange->run(dt, side_of(spec.fluid), side_of(spec.solid), operators,
                               iteration && window > 0 ? &applied_exchange_impulses : nullptr);
    answered_exchange_impulses = std::move(impulses.on_exchange_mesh);
    max_momentum_balance_error =
        std::max(max_momentum_balance_error, impulses.momentum_balance_error);
    if (spec.solved_by == job::ExchangeSolver::fluid)
      out[spec.fluid][fields::drag_coefficient.name] =
          std::make_shared<const std::vector<double>>(std::move(impulses.drag_coefficient));
    else
      out[spec.fluid][fields::momentum_exchange_impulse.name] =
          std::make_shared<const std::vector<double>>(std::move(impulses.fluid));
    out[spec.solid][fields::momentum_exchange_impulse.name] =
        std::make_shared<const std::vector<double>>(std::move(impulses.solid));
  }

  void exchange_energy(FieldsByPeer& out) {
    if (!energy_exchange) return;
    auto scope = summary.phases().measure("exchange");
    const job::EnergyExchangeSpec& spec = *job.energy_exchange;
    const double dt = window == 0 ? 0.0 : job.window;
    auto heat = energy_exchange->run(dt, side_of(spec.fluid), side_of(spec.solid), operators,
                                     iteration && window > 0 ? &applied_exchange_heat : nullptr);
    answered_exchange_heat = std::move(heat.on_exchange_mesh);
    max_energy_balance_error = std::max(max_energy_balance_error, heat.energy_balance_error);
    out[spec.fluid][fields::heat_exchange_energy.name] =
        std::make_shared<const std::vector<double>>(std::move(heat.fluid));
    out[spec.solid][fields::heat_exchange_energy.name] =
        std::make_shared<const std::vector<double>>(std::move(heat.solid));
  }

  // The coupler's part of an explicit window, in order: the participants'
  // answer (their fields mapped to the readers, then the exchange steps),
  // sent, recorded, and the next window begun.
  void map_and_send() {
    const double t = window_time(window);
    FieldsByPeer answer = window_answer();
    send_fields(t, answer);
    record_iterate(answer);
    write_snapshots(t, answer);
    begin_next_window(t);
  }

  // An implicit window: run by the participants until the window iteration
  // accepts their answer, each repetition from the window's start with the
  // next iterate; only the accepted answer is recorded.
  void iterate_window() {
    const double t = window_time(window);
    for (;;) {
      collect_window();
      FieldsByPeer answer = window_answer();
      if (iteration->judge(window, t, answer) != WindowIteration::Verdict::repeat) {
        send_fields(t, answer);
        record_iterate(answer);
        write_snapshots(t, answer);
        begin_next_window(t);
        return;
      }
      send_fields(t, iteration->next());
      record_iterate(iteration->next());
      repeat_window(t);
    }
  }

  // A serial window: `first` runs it on the second's values of the window
  // before, then the second on the first's new values; the second's answer
  // goes to the first with the next window. Implicit: repeated, both from
  // the window's start, until the window iteration accepts the answer.
  void serial_window() {
    const double t = window_time(window);
    const std::string& first = job.coupling.first;
    const std::string& second = job.coupling.second;
    for (std::size_t k = 1;; ++k) {
      collect_window(&first);
      FieldsByPeer answer = map_exchanged_fields(&second);
      send_fields(t, answer);
      tell(second, k == 1 ? MessageType::window_begin : MessageType::window_repeat, window, t);
      collect_window(&second);
      answer.merge(map_exchanged_fields(&first));
      if (!iteration || iteration->judge(window, t, answer) != WindowIteration::Verdict::repeat) {
        send_fields(t, part_of(answer, first));
        record_iterate(answer);
        write_snapshots(t, answer);
        const bool last = window >= job.windows();
        tell(first, last ? MessageType::finish : MessageType::window_begin, window + 1, t);
        if (last) tell(second, MessageType::finish, window + 1, t);
        return;
      }
      send_fields(t, part_of(iteration->next(), first));
      record_iterate(iteration->next());
      tell(first, MessageType::window_repeat, window, t);
    }
  }

  // Window 0 of a serial scheme: the first participant begins window 1 on
  // the second's initial fields; the second gets the first's, the start of
  // what it reads over window 1, and waits for the first's answer.
  void serial_start() {
    const double t = window_time(0);
    const std::string& first = job.coupling.first;
    FieldsByPeer initial = map_exchanged_fields(&first);
    send_fields(t, initial);
    FieldsByPeer to_second = map_exchanged_fields(&job.coupling.second);
    send_fields(t, to_second);
    initial.merge(std::move(to_second));
    record_iterate(initial);
    write_snapshots(t, initial);
    tell(first, MessageType::window_begin, 1, t);
  }

  static FieldsByPeer part_of(const FieldsByPeer& fields, const std::string& name) {
    FieldsByPeer part;
    if (auto it = fields.find(name); it != fields.end()) part.insert(*it);
    return part;
  }

  void tell(const std::string& name, MessageType type, std::size_t w, double t) {
    com::Message m = message(type, t);
    m.header.window = w;
    send(name, m);
  }

  FieldsByPeer window_answer() {
    FieldsByPeer answer = map_exchanged_fields();
    exchange_momentum(answer);
    exchange_energy(answer);
    return answer;
  }

  // What the participants run the window with next; the exchange's momentum
  // is never accelerated, so it is the last answer's.
  void record_iterate(const FieldsByPeer& x) {
    if (!iteration) return;
    iteration->sent(x);
    applied_exchange_impulses = answered_exchange_impulses;
    applied_exchange_heat = answered_exchange_heat;
  }

  // The summary's `coupling` section (its median sorts every window's count:
  // made when the summary is written, not every window).
  void record_coupling() {
    if (iteration) summary.set_section("coupling", iteration->summary());
  }

  void repeat_window(double t) {
    for (const auto& [name, peer] : peers) send(name, message(MessageType::window_repeat, t));
  }

  // Implicit schemes: the iteration's measures, in the units the
  // participants declared for the fields they read, and the bounds they
  // declared for the accelerated ones.
  void start_window_iteration() {
    if (!job.coupling.is_implicit()) return;
    std::map<std::string, std::string> units;
    for (const job::ConvergenceMeasure& m : job.coupling.convergence)
      units[m.field.label()] =
          declared(peers.at(m.field.participant).hello.reads, m.field.field).unit;
    std::map<std::string, WindowIteration::Bounds> bounds;
    for (const job::SentField& f : job.coupling.accelerated) {
      const FieldSpec& spec = declared(peers.at(f.participant).hello.reads, f.field);
      bounds[f.label()] = {spec.lower_bound, spec.upper_bound};
    }
    iteration.emplace(job.coupling, units, bounds, options.output_dir / "coupling_iterations.csv");
  }

  // The exchanges' fields mapped to their readers, or (serial schemes) to one.
  FieldsByPeer map_exchanged_fields(const std::string* only_to = nullptr) {
    auto scope = summary.phases().measure("mapping");
    FieldsByPeer received;
    for (std::size_t i = 0; i < job.exchanges.size(); ++i) {
      const job::ExchangeSpec& x = job.exchanges[i];
      if (only_to && x.to != *only_to) continue;
      const Peer& to = peers.at(x.to);
      const FieldSpec& spec = declared(to.hello.reads, x.field);
      const std::vector<double>& source = peers.at(x.from).written.at(x.field);
      std::vector<double> target = operator_for(i).apply(source, spec.components);
      if (x.mapping.bounds) keep_within_bounds(x, to.meshes.at(spec.mesh), spec.components, target);
      if (x.mapping.constraint == mapping::Constraint::conservative)
        measure_conservation(source, target);
      received[x.to][x.field] = std::make_shared<const std::vector<double>>(std::move(target));
    }
    return received;
  }

  // A bounded field's values per control volume held within the exchange's
  // bounds, the excess moved to neighbours (bounded_redistribution.hpp).
  static void keep_within_bounds(const job::ExchangeSpec& x, const Mesh& target_mesh,
                                 int components, std::vector<double>& target) {
    const auto per_element = static_cast<std::size_t>(components);
    std::vector<double> fraction(target.size());
    for (std::size_t e = 0; e < target.size(); ++e)
      fraction[e] = target[e] / target_mesh.control_volume(e / per_element);
    mapping::redistribute_to_bounds(target_mesh, fraction, x.mapping.bounds->first,
                                    x.mapping.bounds->second);
    for (std::size_t e = 0; e < target.size(); ++e)
      target[e] = fraction[e] * target_mesh.control_volume(e / per_element);
  }

  // |sum target - sum source| / sum |source| of a conservative mapping.
  void measure_conservation(std::span<const double> source, std::span<const double> target) {
    const double scale = std::max(abs_sum(source), 1e-300);
    max_conservation_error =
        std::max(max_conservation_error, std::abs(sum(target) - sum(source)) / scale);
  }

  void send_fields(double t, const FieldsByPeer& received) {
    for (const auto& [peer_name, fields] : received) {
      const Peer& to = peers.at(peer_name);
      for (const auto& [field, values] : fields) {
        const FieldSpec& spec = declared(to.hello.reads, field);
        send(peer_name,
             com::make_field_message(options.job_id, com::coupler_peer, window, t, field, spec.mesh,
                                     values, static_cast<std::uint32_t>(spec.components)));
      }
    }
  }

  // window_begin of the next window, or finish after the last; at a
  // checkpoint's window end the window_begin names where each participant
  // writes its state, and the checkpoint is completed before going on.
  void begin_next_window(double t) {
    const bool last = window >= job.windows();
    if (!last && options.checkpoint_every &&
        (stop_at_next_window || options.checkpoint_every->due(window, job.window))) {
      write_checkpoint(t, stop_at_next_window);
      stopped_at_checkpoint = stop_at_next_window;
      return;
    }
    for (const auto& [name, peer] : peers) {
      com::Message m = message(last ? MessageType::finish : MessageType::window_begin, t);
      m.header.window = window + 1;
      send(name, m);
    }
  }

  // Every participant writes its part into the checkpoint's partial
  // directory, the coupler its own (coupler.h5) and the manifest, and the
  // directory is renamed into place (architecture.md §14).
  void write_checkpoint(double t, bool then_stop) {
    auto scope = summary.phases().measure("checkpoint");
    const std::filesystem::path dir = checkpoints->begin(window);
    for (const auto& [name, peer] : peers) {
      std::filesystem::create_directories(dir / name);
      const nlohmann::json request{{"checkpoint_directory", (dir / name).string()},
                                   {"then_stop", then_stop}};
      send(name, com::make_text_message(MessageType::window_begin, options.job_id,
                                        com::coupler_peer, window + 1, t, request.dump()));
    }
    await_checkpoint_parts();
    write_coupler_state(dir / coupler_state_file, t);
    checkpoint::Manifest manifest;
    manifest.cosim_version = COSIM_VERSION;
    manifest.job_name = job.name;
    manifest.config_hash = job.config_hash;
    manifest.config_hash_without_ranks = job.config_hash_without_ranks;
    for (const auto& p : job.participants) manifest.ranks[p.name] = p.ranks;
    for (const auto& [name, peer] : peers) manifest.participants.push_back(name);
    manifest.scheme = job.coupling.is_implicit() ? "implicit" : "explicit";
    manifest.window = window;
    manifest.time = t;
    checkpoint::write_manifest(dir, manifest);
    const auto final_dir = checkpoints->commit(window);
    ++checkpoints_written;
    summary.set_section("checkpoints", {{"written", checkpoints_written},
                                        {"last", final_dir.string()},
                                        {"last_window", window},
                                        {"last_time_s", t},
                                        {"kept", options.checkpoints_kept}});
    spdlog::info("checkpoint of window {} (t = {:.6g} s) written: {}", window, t,
                 final_dir.string());
  }

  // Waits for every participant's checkpoint_done; what a participant sends
  // for the next window meanwhile is kept for it.
  void await_checkpoint_parts() {
    std::set<std::string> done;
    const auto deadline =
        Clock::now() + std::chrono::milliseconds(static_cast<long>(job.window_timeout_s * 1e3));
    while (done.size() < peers.size()) {
      auto r = receive(deadline,
                       fmt::format("the checkpoint of window {} (window_timeout {} s)", window,
                                   job.window_timeout_s),
                       false);
      if (!r->admitted) {
        drop_stranger(*r);
        continue;
      }
      const com::Header& h = r->message.header;
      check_signature(r->peer, h);
      if (h.type == MessageType::abort) throw participant_abort(r->peer, r->message);
      if (h.type != MessageType::checkpoint_done) {
        if (!done.count(r->peer))
          throw ProtocolError(r->peer, fmt::format("sent '{}' before its part of the checkpoint "
                                                   "of window {}",
                                                   com::to_string(h.type), window));
        deferred.push_back(std::move(*r));
        continue;
      }
      if (h.window != window + 1 || done.count(r->peer))
        throw ProtocolError(r->peer, fmt::format("sent checkpoint_done for window {} during the "
                                                 "checkpoint of window {}",
                                                 h.window, window));
      done.insert(r->peer);
    }
  }

  // The coupler's state between windows: where the run is, the meshes it
  // maps between, the output schedule, the metrics, and (implicit schemes)
  // the window iteration's state.
  void write_coupler_state(const std::filesystem::path& file, double t) const {
    StateFileWriter out(file, coupler_state_kind, coupler_state_version);
    out.integer("window", static_cast<std::int64_t>(window));
    out.number("time", t);
    out.number("next_output_time", next_output_time);
    out.number("max_conservation_error", max_conservation_error);
    out.number("max_momentum_balance_error", max_momentum_balance_error);
    out.number("max_energy_balance_error", max_energy_balance_error);
    for (const auto& [name, peer] : peers)
      for (const auto& [mesh_name, mesh] : peer.meshes)
        checkpoint::write_mesh(out, "mesh." + name + "." + mesh_name, mesh);
    if (iteration) {
      iteration->save(out);
      out.numbers("exchange.applied.fluid", applied_exchange_impulses.fluid);
      out.numbers("exchange.applied.solid", applied_exchange_impulses.solid);
      if (energy_exchange) {
        out.numbers("exchange.heat_applied.fluid", applied_exchange_heat.fluid);
        out.numbers("exchange.heat_applied.solid", applied_exchange_heat.solid);
      }
    }
    out.commit();
  }

  // Continues from a checkpoint: the state write_coupler_state() left.
  void restore_coupler_state() {
    const StateFileReader in(options.restart / coupler_state_file, coupler_state_kind,
                             coupler_state_version);
    if (static_cast<std::size_t>(in.integer("window")) != options.restart_window)
      throw InputError(fmt::format("{}: holds window {}, its manifest says {}", in.file().string(),
                                   in.integer("window"), options.restart_window));
    next_output_time = in.number("next_output_time");
    max_conservation_error = in.number("max_conservation_error");
    max_momentum_balance_error = in.number("max_momentum_balance_error");
    max_energy_balance_error = in.number("max_energy_balance_error");
    for (auto& [name, peer] : peers)
      for (const com::MeshDeclaration& d : peer.hello.meshes) {
        const std::string key = "mesh." + name + "." + d.name;
        if (!in.has(key + ".kind")) continue;
        peer.meshes[d.name] = checkpoint::read_mesh(in, key, d.name);
        peer.mesh_version[d.name] = 1;
      }
    if (iteration) {
      std::vector<std::pair<std::string, std::string>> sent;
      for (const job::ExchangeSpec& x : job.exchanges) sent.emplace_back(x.to, x.field);
      if (job.momentum_exchange) {
        sent.emplace_back(job.momentum_exchange->fluid, fields::drag_coefficient.name);
        sent.emplace_back(job.momentum_exchange->fluid, fields::momentum_exchange_impulse.name);
        sent.emplace_back(job.momentum_exchange->solid, fields::momentum_exchange_impulse.name);
      }
      if (job.energy_exchange) {
        sent.emplace_back(job.energy_exchange->fluid, fields::heat_exchange_energy.name);
        sent.emplace_back(job.energy_exchange->solid, fields::heat_exchange_energy.name);
      }
      iteration->restore(in, sent);
      applied_exchange_impulses.fluid = in.numbers("exchange.applied.fluid");
      applied_exchange_impulses.solid = in.numbers("exchange.applied.solid");
      if (energy_exchange) {
        applied_exchange_heat.fluid = in.numbers("exchange.heat_applied.fluid");
        applied_exchange_heat.solid = in.numbers("exchange.heat_applied.solid");
      }
    }
    summary.set_section("restart", {{"from", options.restart.string()},
                                    {"window", options.restart_window},
                                    {"time_s", window_time(options.restart_window)}});
    spdlog::info("continuing from the checkpoint of window {} (t = {:.6g} s): {}",
                 options.restart_window, window_time(options.restart_window),
                 options.restart.string());
  }

  void write_snapshots(double t, const FieldsByPeer& data) {
    if (job.output_every <= 0.0 || t + time_tolerance * job.window < next_output_time) return;
    auto scope = summary.phases().measure("output");
    next_output_time = t + job.output_every;
    for (const auto& [peer_name, fields] : data) {
      const Peer& peer = peers.at(peer_name);
      std::map<std::string, SnapshotFields> per_mesh;
      for (const auto& [field, values] : fields) {
        const FieldSpec& spec = declared(peer.hello.reads, field);
        per_mesh[spec.mesh][field] = FieldView{*values, spec.components, spec.unit};
      }
      for (const auto& [mesh_name, snapshot] : per_mesh) {
        const std::string key = peer_name + "_" + mesh_name;
        auto& writer = snapshot_writers[key];
        const Mesh& mesh = peer.meshes.at(mesh_name);
        if (!writer)
          writer = std::make_unique<SnapshotWriter>(options.output_dir / "exchanged", key, mesh);
        if (mesh.kind() == MeshKind::point_cloud)
          writer->write(t, mesh, snapshot);
        else
          writer->write(t, snapshot);
      }
    }
  }

  void abort_all(const std::string& reason) {
    for (const auto& [name, peer] : peers) {
      if (!peer.connected) continue;
      try {
        transport.send(name, com::make_text_message(MessageType::abort, options.job_id,
                                                    com::coupler_peer, window, 0.0, reason));
      } catch (const std::exception&) {
      }
    }
  }
};

Coupler::Coupler(const job::Job& job, com::Hub& transport, runtime::Supervisor* supervisor,
                 RunSummary& summary, CouplerOptions options)
    : impl_(std::make_unique<Impl>(job, transport, supervisor, summary, std::move(options))) {}

Coupler::~Coupler() = default;

bool Coupler::stopped_at_checkpoint() const {
  return impl_->stopped_at_checkpoint;
}

void Coupler::run() {
  Impl& s = *impl_;
  const std::size_t windows = s.job.windows();
  Progress progress(s.job.start_time, s.job.end_time, windows, s.options.progress_on_terminal);
  try {
    s.admit_participants();
    s.start_window_iteration();
    spdlog::info("all {} participants connected; {} windows of {} s from t = {} s to {} s",
                 s.peers.size(), windows, s.job.window, s.job.start_time, s.job.end_time);
    s.next_output_time = s.job.start_time;
    std::size_t first_window = 0;
    if (!s.options.restart.empty()) {
      s.restore_coupler_state();
      first_window = s.options.restart_window + 1;
    }
    auto last_summary = std::chrono::steady_clock::now();
    for (s.window = first_window; s.window <= windows; ++s.window) {
      if (s.window == 0) {
        s.collect_window();
        s.check_explicit_stability();
        if (s.job.coupling.is_serial())
          s.serial_start();
        else
          s.map_and_send();
      } else if (s.job.coupling.is_serial()) {
        s.serial_window();
      } else if (s.iteration) {
        s.iterate_window();
      } else {
        s.collect_window();
        s.map_and_send();
      }
      s.summary.set_windows(static_cast<std::int64_t>(s.window));
      if (s.stopped_at_checkpoint) break;
      s.summary.set_metric("max_conservative_mapping_error", s.max_conservation_error, "1");
      if (s.momentum_exchange)
        s.summary.set_metric("max_momentum_exchange_balance_error", s.max_momentum_balance_error,
                             "1");
      if (s.energy_exchange)
        s.summary.set_metric("max_energy_exchange_balance_error", s.max_energy_balance_error, "1");
      progress.update(s.window, s.window_time(s.window),
                      s.iteration && s.window > 0 ? s.iteration->last_window_iterations() : 0);
      s.summary.set_progress(s.window_time(s.window), s.job.end_time);
      const auto now = std::chrono::steady_clock::now();
      if (s.window % 100 == 0 || now - last_summary > std::chrono::seconds(2)) {
        s.record_coupling();
        s.summary.write();
        last_summary = now;
      }
    }
    progress.finish();
    s.record_coupling();
  } catch (const std::exception& e) {
    s.record_coupling();
    progress.finish();
    s.abort_all(e.what());
    throw;
  }
  nlohmann::json participants = nlohmann::json::object();
  for (const auto& [name, peer] : s.peers)
    participants[name] = {{"program", peer.hello.program}, {"pid", peer.hello.pid}};
  s.summary.set_section("participants", participants);
}

}  // namespace cosim::cplscheme

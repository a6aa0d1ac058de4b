// cosim_test_participant: a participant for end-to-end tests of the coupler.
//
// It declares one mesh, writes analytic fields, sub-cycles its own time step
// inside every window, checks the fields it reads against the analytic
// functions its partner writes, and logs every total it sends and receives
// to <output>/<field>_<direction>.csv so tests can check conservation. Fault
// injection (--crash-at-window, --hang-at-window, --raise <signal> --raise-at
// <phase>) exercises the coupler's supervision.

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <thread>

#include "cosim/config/document.hpp"
#include "cosim/config/schema.hpp"
#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "cosim/participant.hpp"
#include "cosim/runtime/stop_request.hpp"
#ifdef COSIM_TEST_PARTICIPANT_MPI
#include "cosim/runtime/mpi_session.hpp"
#endif

namespace {

using cosim::config::Node;
using cosim::config::Schema;

// f(x, t) = c0 + c1 x + c2 y + c3 z + c4 t
struct LinearFunction {
  std::vector<double> c{0, 0, 0, 0, 0};
  double operator()(const cosim::Vec3& x, double t) const {
    return c[0] + c[1] * x[0] + c[2] * x[1] + c[3] * x[2] + c[4] * t;
  }
};

struct FieldConfig {
  cosim::FieldSpec spec;
  LinearFunction function;  // writes: the value (state) or rate per unit volume (integral)
  double tolerance = 0.0;   // reads of state fields: max |read - f| allowed
  bool check = false;
  // Check at every sub-step (from this window on) instead of at window starts
  // only: with linear extrapolation a field linear in time reads exactly.
  long check_every_step_from_window = 0;
  // Writes: f + coefficient * (the read field at the step's end), a
  // participant whose answer depends on what it reads (implicit coupling's
  // fixed-point problems).
  std::string response_to;
  double response_coefficient = 0.0;
};

// Optional dynamics: a velocity state per element that a body force drives
// and the received impulse changes, u <- u + J / (rho_bar V) at each window
// start, then u <- u + f / rho_bar dt every sub-step; `velocity` is written.
struct Dynamics {
  std::string velocity;
  std::string impulse;
  double bulk_density = 1.0;
  std::vector<double> body_force;
};

// Optional ordinary differential equation: a written field y with
// dy/dt = coefficient * z(t), z a read field, integrated by the midpoint
// rule with z read at each step's middle (time interpolation tests).
struct Ode {
  std::string state;
  std::string rate_from;
  double coefficient = 0.0;
  double initial = 0.0;
};

struct Config {
  double dt = 1e-3;
  std::optional<Dynamics> dynamics;
  std::optional<Ode> ode;
  double end_time = 1.0;
  cosim::Mesh mesh;
  std::vector<FieldConfig> writes;
  std::vector<FieldConfig> reads;
};

Schema config_schema() {
  Schema mesh = Schema::object("Uniform grid of the participant.");
  mesh.required("dim", Schema::integer().range(1, 3), "Dimension.")
      .required("origin", Schema::vector(1, 3), "Lower corner [m].")
      .required("spacing", Schema::vector(1, 3), "Cell size [m].")
      .required("cells", Schema::vector(1, 3), "Cells per direction.")
      .optional("location", Schema::one_of({"cell", "node"}).default_value("cell"),
                "Where values live.");
  Schema response = Schema::object("A written field's dependence on a read one.");
  response.required("read", Schema::string().non_empty(), "The read field.")
      .required("coefficient", Schema::number(), "Its factor.");
  Schema field = Schema::object("A field.");
  field.required("name", Schema::string().non_empty(), "Field name.")
      .optional("quantity", Schema::one_of({"intensive", "extensive"}).default_value("intensive"),
                "intensive | extensive.")
      .optional("time", Schema::one_of({"state", "integral"}).default_value("state"),
                "state | integral.")
      .optional("unit", Schema::string().default_value("1"), "SI unit.")
      .optional("components", Schema::integer().range(1, 3).default_value("1"),
                "Values per element (each component takes `function`).")
      .optional("function", Schema::vector(5, 5).default_value("[0,0,0,0,0]"),
                "c0 + c1 x + c2 y + c3 z + c4 t.")
      .optional("check_every_step_from_window", Schema::integer().positive(),
                "Also check the read at every sub-step from this window on.")
      .optional("tolerance", Schema::number().non_negative(),
                "Check reads against `function` to this tolerance.")
      .optional("response", response,
                "Writes only: add coefficient times a read field (same mesh) to `function`.");
  Schema dynamics = Schema::object("A velocity state driven by a body force and the impulse read.");
  dynamics.required("velocity", Schema::string().non_empty(), "Written field holding the velocity.")
      .required("impulse", Schema::string().non_empty(), "Read field of momentum [kg m/s].")
      .required("bulk_density", Schema::number().positive().unit("kg/m^3"), "rho_bar.")
      .required("body_force", Schema::vector(1, 3), "Force per unit volume [N/m^3].");
  Schema ode = Schema::object("A written field y with dy/dt = coefficient z(t), z read.");
  ode.required("state", Schema::string().non_empty(), "The written field y.")
      .required("rate_from", Schema::string().non_empty(), "The read field z.")
      .required("coefficient", Schema::number(), "Its factor.")
      .required("initial", Schema::number(), "y at the start.");
  Schema s = Schema::file("test_participant", "Test participant for the coupler's tests.");
  s.required("dt", Schema::number().positive().unit("s"), "Own time step.")
      .optional("end_time", Schema::number().positive().unit("s").default_value("1"),
                "End time when standalone.")
      .required("mesh", mesh, "Its mesh.")
      .optional("writes", Schema::sequence(field), "Fields written.")
      .optional("reads", Schema::sequence(field), "Fields read.")
      .optional("dynamics", dynamics, "Velocity dynamics (Darcy tests).")
      .optional("ode", ode, "dy/dt = coefficient z(t) for a written y and a read z.");
  return s;
}

FieldConfig read_field(const Node& f) {
  FieldConfig c;
  c.spec.name = f["name"].as<std::string>();
  c.spec.mesh = "grid";
  c.spec.unit = f.get<std::string>("unit", "1");
  c.spec.components = f.get<int>("components", 1);
  c.spec.quantity = f.get<std::string>("quantity", "intensive") == "extensive"
                        ? cosim::Quantity::extensive
                        : cosim::Quantity::intensive;
  c.spec.time = f.get<std::string>("time", "state") == "integral" ? cosim::TimeTreatment::integral
                                                                  : cosim::TimeTreatment::state;
  c.function.c = f.get<std::vector<double>>("function", {0, 0, 0, 0, 0});
  c.check_every_step_from_window = f.get<long>("check_every_step_from_window", 0);
  if (auto t = f.find("tolerance")) {
    c.tolerance = t->as<double>();
    c.check = true;
  }
  if (auto r = f.find("response")) {
    c.response_to = (*r)["read"].as<std::string>();
    c.response_coefficient = (*r)["coefficient"].as<double>();
  }
  return c;
}

Config load_config(const std::string& file) {
  const auto doc = cosim::config::Document::load_file(file);
  const Node root = doc.root();
  config_schema().validate(root);
  Config c;
  c.dt = root["dt"].as<double>();
  c.end_time = root.get<double>("end_time", 1.0);
  const Node m = root["mesh"];
  cosim::UniformGrid g;
  g.dim = m["dim"].as<int>();
  const auto origin = m["origin"].as<std::vector<double>>();
  const auto spacing = m["spacing"].as<std::vector<double>>();
  const auto cells = m["cells"].as<std::vector<double>>();
  if (origin.size() != static_cast<std::size_t>(g.dim) ||
      spacing.size() != static_cast<std::size_t>(g.dim) ||
      cells.size() != static_cast<std::size_t>(g.dim))
    m.fail("origin, spacing and cells need one value per dimension");
  for (int d = 0; d < g.dim; ++d) {
    g.origin[d] = origin[d];
    g.spacing[d] = spacing[d];
    g.cells[d] = static_cast<std::int64_t>(cells[d]);
  }
  g.location = m.get<std::string>("location", "cell") == "node" ? cosim::GridLocation::node
                                                                : cosim::GridLocation::cell;
  c.mesh = cosim::Mesh{"grid", g};
  cosim::validate(c.mesh);
  if (auto w = root.find("writes"))
    for (const Node& f : w->items()) c.writes.push_back(read_field(f));
  if (auto r = root.find("reads"))
    for (const Node& f : r->items()) c.reads.push_back(read_field(f));
  if (auto d = root.find("dynamics")) {
    Dynamics dyn;
    dyn.velocity = (*d)["velocity"].as<std::string>();
    dyn.impulse = (*d)["impulse"].as<std::string>();
    dyn.bulk_density = (*d)["bulk_density"].as<double>();
    dyn.body_force = (*d)["body_force"].as<std::vector<double>>();
    c.dynamics = dyn;
  }
  if (auto o = root.find("ode"))
    c.ode = Ode{(*o)["state"].as<std::string>(), (*o)["rate_from"].as<std::string>(),
                (*o)["coefficient"].as<double>(), (*o)["initial"].as<double>()};
  return c;
}

double total(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

// A signal the participant sends itself at one phase of the run:
// `startup` (before it connects), `window:N` (at the start of window N) or
// `end` (after the last window, before it finalizes).
struct RaisedSignal {
  int signal = 0;
  std::string phase;
  void at(const std::string& now) const {
    if (signal != 0 && phase == now) ::raise(signal);
  }
};

int signal_number(const std::string& name) {
  for (const auto& [n, number] :
       std::initializer_list<std::pair<const char*, int>>{{"SIGKILL", SIGKILL},
                                                          {"SIGSTOP", SIGSTOP},
                                                          {"SIGSEGV", SIGSEGV},
                                                          {"SIGTERM", SIGTERM},
                                                          {"SIGABRT", SIGABRT}})
    if (name == n) return number;
  throw cosim::InputError("--raise: unknown signal '" + name + "'");
}

struct Capabilities {
  bool repeatable = true;
  bool checkpointable = true;
};

// On several ranks (an MPMD job's program on `ranks` ranks): this rank holds
// the values of a contiguous range of the grid's flat indices.
struct Part {
  int rank = 0;
  int ranks = 1;
  bool declared = true;  // false: declares its mesh whole, as a program that cannot run on ranks
  int ghosts = 0;        // elements of each neighbour's range also held (read, never sent)
};

// Fault injection: what the participant does besides its fields.
struct Faults {
  long crash_at_window = 0;
  long hang_at_window = 0;
  double window_delay_s = 0.0;  // a slow solver: sleeps at every window's start
  RaisedSignal raised;
};

int run(const Config& config, const cosim::CouplingEndpoint& endpoint, const std::string& output,
        const Faults& faults, Capabilities capabilities, cosim::RunSummary& summary, Part part) {
  const long crash_at_window = faults.crash_at_window;
  const long hang_at_window = faults.hang_at_window;
  const RaisedSignal& raised = faults.raised;
  cosim::create_output_directory(output);
  std::ofstream(std::filesystem::path(output) / "pid") << ::getpid() << "\n";
  // One CSV per field and direction: <output>/<field>_<sent|applied|read>.csv;
  // rows wait until the window they belong to is complete, so a repeated
  // window leaves none.
  std::map<std::string, cosim::TimeSeriesWriter> logs;
  struct Row {
    std::string key;
    std::vector<double> values;
  };
  std::vector<Row> pending_rows;
  auto log = [&](const std::string& field, const std::string& direction, double window, double t,
                 double sum, double max_error) {
    pending_rows.push_back({field + "_" + direction, {window, t, sum, max_error}});
  };
  auto write_rows = [&] {
    for (const Row& row : pending_rows) {
      auto it = logs.find(row.key);
      if (it == logs.end())
        it = logs.emplace(row.key, cosim::TimeSeriesWriter(
                                       std::filesystem::path(output) / (row.key + ".csv"),
                                       {"window", "time [s]", "total", "max_error"}))
                 .first;
      it->second.append(row.values);
    }
    pending_rows.clear();
  };

  const cosim::Mesh& mesh = config.mesh;
  cosim::MeshPart elements;
  const auto whole = static_cast<std::int64_t>(mesh.size());
  const Part held_part = part.declared ? part : Part{};  // else the whole mesh on every rank
  const std::int64_t first = whole * held_part.rank / held_part.ranks;
  const std::int64_t end = whole * (held_part.rank + 1) / held_part.ranks;
  for (std::int64_t e = std::max<std::int64_t>(0, first - part.ghosts);
       e < std::min(whole, end + part.ghosts); ++e) {
    elements.elements.push_back(e);
    elements.owned.push_back(e >= first && e < end ? 1 : 0);
  }
  auto position = [&](std::size_t e) {
    return mesh.position(static_cast<std::size_t>(elements.elements[e]));
  };
  auto control_volume = [&](std::size_t e) {
    return mesh.control_volume(static_cast<std::size_t>(elements.elements[e]));
  };
  const std::size_t held = elements.size();
  // A field's total over the elements this rank owns.
  auto owned_total = [&](const std::vector<double>& v) {
    const std::size_t components = held == 0 ? 1 : v.size() / held;
    double sum = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (elements.owns(i / components)) sum += v[i];
    return sum;
  };

  cosim::Participant participant(endpoint.name_or("test_participant"), endpoint);
  if (part.ranks > 1 && part.declared)
    participant.declare_mesh(config.mesh, elements);
  else
    participant.declare_mesh(config.mesh);
  for (const auto& w : config.writes) participant.declare_write(w.spec);
  for (const auto& r : config.reads) participant.declare_read(r.spec);
  if (capabilities.repeatable) participant.declare_repeatable();
  if (capabilities.checkpointable) participant.declare_checkpointable();

  auto values_of = [&](const FieldConfig& f, double t) {
    const auto components = static_cast<std::size_t>(f.spec.components);
    std::vector<double> v(held * components);
    for (std::size_t e = 0; e < held; ++e) {
      double value = f.function(position(e), t);
      if (f.spec.time == cosim::TimeTreatment::integral) value *= control_volume(e);
      for (std::size_t c = 0; c < components; ++c) v[e * components + c] = value;
    }
    return v;
  };
  // Initial data: state fields at the start time.
  for (const auto& w : config.writes) participant.write(w.spec.name, values_of(w, 0.0));
  std::vector<double> ode_state;
  if (config.ode) {
    ode_state.assign(participant.field_size(config.ode->state), config.ode->initial);
    participant.write(config.ode->state, ode_state);
  }

  raised.at("startup");
  participant.initialize(0.0, config.end_time);

  std::vector<double> velocity;  // dynamics state, element-major
  int velocity_components = 1;
  if (config.dynamics) {
    const auto& w = *std::find_if(config.writes.begin(), config.writes.end(), [&](auto& f) {
      return f.spec.name == config.dynamics->velocity;
    });
    velocity = values_of(w, 0.0);
    velocity_components = w.spec.components;
    if (config.dynamics->body_force.size() != static_cast<std::size_t>(velocity_components))
      throw cosim::InputError("dynamics.body_force needs one value per velocity component");
  }
  // At each window start: apply the whole impulse received, and log the
  // velocity after the exchange (its mean per component).
  auto apply_impulse = [&]() {
    if (!config.dynamics) return;
    const auto impulse = participant.read(config.dynamics->impulse);
    const auto comps = static_cast<std::size_t>(velocity_components);
    std::vector<double> mean(3, 0.0);
    for (std::size_t i = 0; i < velocity.size(); ++i) {
      velocity[i] += impulse[i] / (config.dynamics->bulk_density * control_volume(i / comps));
      mean[i % comps] += velocity[i] / static_cast<double>(held);
    }
    log(config.dynamics->velocity, "after_exchange",
        static_cast<double>(participant.window_index()), participant.time(), mean[0],
        comps > 1 ? mean[1] : 0.0);
  };
  std::map<std::string, std::vector<double>> sent_integral;
  for (const auto& w : config.writes)
    sent_integral[w.spec.name].assign(participant.field_size(w.spec.name), 0.0);

  auto check_reads = [&](bool sub_step) {
    for (const auto& r : config.reads) {
      if (r.spec.time == cosim::TimeTreatment::integral) continue;
      if (sub_step &&
          (r.check_every_step_from_window == 0 ||
           static_cast<long>(participant.window_index()) < r.check_every_step_from_window))
        continue;
      const auto v = participant.read(r.spec.name);
      double max_error = 0.0;
      if (r.check) {
        // At a window start: what the partner wrote at the end of the
        // previous window. Inside a window: the extrapolation to now.
        const double t_written = participant.time();
        const auto components = static_cast<std::size_t>(r.spec.components);
        for (std::size_t i = 0; i < v.size(); ++i)
          max_error =
              std::max(max_error, std::abs(v[i] - r.function(position(i / components), t_written)));
        if (max_error > r.tolerance)
          throw cosim::NumericalError(
              fmt::format("read '{}' at t = {} s: error {:.3e} exceeds {:.3e}", r.spec.name,
                          t_written, max_error, r.tolerance));
      }
      if (!sub_step)
        log(r.spec.name, "read", static_cast<double>(participant.window_index()),
            participant.time(), owned_total(v), max_error);
    }
  };

  std::map<std::string, std::vector<double>> received_integral;
  for (const auto& r : config.reads)
    received_integral[r.spec.name].assign(participant.field_size(r.spec.name), 0.0);
  // The state a repeated window starts again from (implicit coupling).
  struct State {
    std::vector<double> velocity, ode_state;
    std::map<std::string, std::vector<double>> sent_integral, received_integral;
  } saved;
  // The same state in a checkpoint (the integrals are zero at a window's end).
  constexpr const char* state_kind = "cosim_test_participant";
  auto write_checkpoint = [&] {
    cosim::StateFileWriter out(participant.checkpoint_directory() / "state.h5", state_kind, 1);
    out.numbers("velocity", velocity);
    out.numbers("ode_state", ode_state);
    out.commit();
    participant.checkpoint_written();
  };
  if (!participant.restart_directory().empty()) {
    const cosim::StateFileReader in(participant.restart_directory() / "state.h5", state_kind, 1);
    in.numbers("velocity", velocity.size(), velocity);
    in.numbers("ode_state", ode_state.size(), ode_state);
  }
  auto begin_window = [&] {
    if (faults.window_delay_s > 0.0)
      std::this_thread::sleep_for(std::chrono::duration<double>(faults.window_delay_s));
    if (participant.must_save_state())
      saved = {velocity, ode_state, sent_integral, received_integral};
    check_reads(false);
    apply_impulse();
  };
  try {
    begin_window();
    while (participant.is_coupling_ongoing()) {
      const std::size_t window = participant.window_index();
      raised.at(fmt::format("window:{}", window));
      if (crash_at_window > 0 && static_cast<long>(window) == crash_at_window)
        throw cosim::NumericalError(fmt::format("crash requested at window {}", window));
      if (hang_at_window > 0 && static_cast<long>(window) == hang_at_window)
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));

      const double dt = std::min(config.dt, participant.max_time_step());
      const double t = participant.time();
      check_reads(true);
      for (const auto& r : config.reads) {
        if (r.spec.time != cosim::TimeTreatment::integral) continue;
        std::vector<double> share(participant.field_size(r.spec.name));
        participant.read_increment(r.spec.name, dt, share);
        auto& acc = received_integral[r.spec.name];
        for (std::size_t e = 0; e < share.size(); ++e) acc[e] += share[e];
      }
      if (config.dynamics) {
        const auto comps = static_cast<std::size_t>(velocity_components);
        for (std::size_t i = 0; i < velocity.size(); ++i)
          velocity[i] +=
              config.dynamics->body_force[i % comps] / config.dynamics->bulk_density * dt;
      }
      if (config.ode) {
        std::vector<double> rate(ode_state.size());
        participant.read(config.ode->rate_from, rate, 0.5 * dt);
        for (std::size_t e = 0; e < ode_state.size(); ++e)
          ode_state[e] += dt * config.ode->coefficient * rate[e];
      }
      for (const auto& w : config.writes) {
        if (config.dynamics && w.spec.name == config.dynamics->velocity) {
          participant.write(w.spec.name, velocity);
          continue;
        }
        if (config.ode && w.spec.name == config.ode->state) {
          participant.write(w.spec.name, ode_state);
          continue;
        }
        auto v = values_of(w, w.spec.time == cosim::TimeTreatment::integral ? t : t + dt);
        if (!w.response_to.empty()) {
          std::vector<double> read(v.size());
          participant.read(w.response_to, read, dt);
          for (std::size_t e = 0; e < v.size(); ++e) v[e] += w.response_coefficient * read[e];
        }
        participant.write(w.spec.name, v);
        if (w.spec.time == cosim::TimeTreatment::integral)
          for (std::size_t e = 0; e < v.size(); ++e) sent_integral[w.spec.name][e] += v[e] * dt;
      }
      participant.advance(dt);
      if (participant.must_restore_state()) {
        velocity = saved.velocity;
        ode_state = saved.ode_state;
        sent_integral = saved.sent_integral;
        received_integral = saved.received_integral;
        pending_rows.clear();
        begin_window();
        continue;
      }
      if (participant.window_index() != window) {  // the window completed
        for (const auto& w : config.writes) {
          if (w.spec.time != cosim::TimeTreatment::integral) continue;
          log(w.spec.name, "sent", static_cast<double>(window), participant.time(),
              owned_total(sent_integral[w.spec.name]), 0.0);
          std::fill(sent_integral[w.spec.name].begin(), sent_integral[w.spec.name].end(), 0.0);
        }
        for (const auto& r : config.reads) {
          if (r.spec.time != cosim::TimeTreatment::integral) continue;
          log(r.spec.name, "applied", static_cast<double>(window), participant.time(),
              owned_total(received_integral[r.spec.name]), 0.0);
          std::fill(received_integral[r.spec.name].begin(), received_integral[r.spec.name].end(),
                    0.0);
        }
        if (config.dynamics) {
          const auto comps = static_cast<std::size_t>(velocity_components);
          std::vector<double> mean(comps, 0.0);
          for (std::size_t i = 0; i < velocity.size(); ++i)
            mean[i % comps] += velocity[i] / static_cast<double>(held);
          log(config.dynamics->velocity, "window_end", static_cast<double>(window),
              participant.time(), mean[0], comps > 1 ? mean[1] : 0.0);
        }
        if (config.ode)
          log(config.ode->state, "window_end", static_cast<double>(window), participant.time(),
              total(ode_state) / static_cast<double>(ode_state.size()), 0.0);
        write_rows();
        if (participant.must_write_checkpoint()) write_checkpoint();
        if (participant.is_coupling_ongoing()) begin_window();
      }
    }
  } catch (const std::exception& e) {
    participant.abort(e.what());  // the coupler learns why before it stops the run
    throw;
  }
  raised.at("end");
  summary.set_windows(static_cast<std::int64_t>(participant.timings().windows));
  participant.finalize();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cosim::runtime::install_stop_handlers();
  CLI::App app{"cosim_test_participant: analytic fields for the coupler's tests"};
  std::string config_file, output, raise_signal;
  bool validate = false, not_repeatable = false, not_checkpointable = false;
  Faults faults;
  int fault_rank = -1;
  bool whole_mesh = false;
  int ghosts = 0;
  cosim::CouplingEndpoint endpoint;
  app.add_option("--config", config_file, "test_participant YAML")->required();
  app.add_option("--output", output, "output directory");
  app.add_flag("--validate", validate, "check the config and exit");
  app.add_option("--crash-at-window", faults.crash_at_window, "fail at the start of this window");
  app.add_option("--hang-at-window", faults.hang_at_window, "stop answering at this window");
  app.add_option("--window-delay", faults.window_delay_s, "seconds to sleep at every window start")
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--raise", raise_signal, "send itself this signal (SIGKILL, SIGSTOP, SIGSEGV...)");
  app.add_option("--raise-at", faults.raised.phase, "when: startup | window:<N> | end");
  app.add_option("--fault-rank", fault_rank,
                 "on several ranks: only this rank crashes, hangs or raises (default: every rank)");
  app.add_flag("--whole-mesh", whole_mesh,
               "on several ranks, declare the mesh whole (a program that cannot run on ranks)");
  app.add_option("--ghosts", ghosts,
                 "on several ranks, also hold this many elements of each neighbour's range")
      ->check(CLI::Range(0, 1000));
  app.add_flag("--not-repeatable", not_repeatable,
               "do not declare that windows can be repeated (implicit schemes refuse it)");
  app.add_flag("--not-checkpointable", not_checkpointable,
               "do not declare that it can write and read checkpoints");
  cosim::add_coupling_options(app, endpoint);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : cosim::to_int(cosim::ExitCode::bad_input);
  }
  try {
    const Config config = load_config(config_file);
    if (validate) {
      std::cout << fmt::format("{}: valid test_participant, {} cells\n", config_file,
                               config.mesh.size());
      return 0;
    }
    if (output.empty()) throw cosim::InputError("--output is required");
    if (!raise_signal.empty()) faults.raised.signal = signal_number(raise_signal);
    // In an MPMD job this program may run on several ranks, each holding a
    // part of the grid; rank r > 0 keeps its files in <output>/ranks/rank_<r>.
    Part part;
#ifdef COSIM_TEST_PARTICIPANT_MPI
    std::optional<cosim::runtime::MpiSession> mpi;
    if (endpoint.uri == "mpi://") {
      mpi.emplace();
      part = {mpi->rank(), mpi->ranks()};
    }
#endif
    part.declared = !whole_mesh;
    part.ghosts = ghosts;
    if (fault_rank >= 0 && fault_rank != part.rank) {
      faults.crash_at_window = faults.hang_at_window = 0;
      faults.raised = {};
    }
    if (part.rank > 0)
      output =
          (std::filesystem::path(output) / "ranks" / fmt::format("rank_{}", part.rank)).string();
    cosim::create_output_directory(output);
    cosim::RunSummary summary(output, "cosim_test_participant");
    summary.write();
    const int code = cosim::run_and_finish(summary, [&] {
      run(config, endpoint, output, faults,
          {.repeatable = !not_repeatable, .checkpointable = !not_checkpointable}, summary, part);
    });
#ifdef COSIM_TEST_PARTICIPANT_MPI
    // A failure before the hello ends the MPI job (the coupler would wait).
    if (mpi) return mpi->finish(code);
#endif
    return code;
  } catch (const cosim::Error& e) {
    std::cerr << "cosim_test_participant: error: " << e.what() << "\n";
    return cosim::to_int(e.code());
  }
}

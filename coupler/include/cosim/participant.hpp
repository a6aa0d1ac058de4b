#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/field.hpp"
#include "cosim/mesh.hpp"

namespace CLI {
class App;
}

// The participant API every solver links (in the spirit of preCICE's
// Participant). A solver's main loop reads:
//
//   cosim::Participant p("soil", endpoint);        // endpoint from the command line
//   p.declare_mesh(grid);
//   p.declare_write({.name = "solid_velocity", .mesh = "mpm_grid", .components = 2, ...});
//   p.declare_read({.name = "pore_pressure", .mesh = "mpm_grid", ...});
//   p.initialize(config.start_time, config.end_time);
//   while (p.is_coupling_ongoing()) {
//     p.read("pore_pressure", pressure);
//     double dt = std::min(my_stable_step(), p.max_time_step());
//     solve(dt);
//     p.write("solid_velocity", velocity);
//     p.advance(dt);                                 // exchanges when the window is complete
//   }
//   p.finalize();
//
// Without an endpoint the same code runs standalone: nothing is exchanged,
// reads return the declared defaults and the solver's own end time applies.
//
// Implicit coupling repeats a window until the exchanged fields converge.
// A solver that can go back to a window's start declares it, saves its state
// when asked, and restores it when the window must run again:
//
//   p.declare_repeatable();                          // before initialize
//   while (p.is_coupling_ongoing()) {
//     if (p.must_save_state()) saved = state;
//     ... step as above ...
//     p.advance(dt);
//     if (p.must_restore_state()) state = saved;     // time() is back at the window's start
//     if (p.is_window_complete()) write_due_outputs();
//   }
//
// Outputs are written only when is_window_complete(): a window that is
// repeated must not leave a trace.
//
// A coupled run can be checkpointed and restarted (architecture.md §14). A
// solver that can write its state and start again from it declares it:
//
//   p.declare_checkpointable();                      // before initialize
//   if (!p.restart_directory().empty()) state = read_state(p.restart_directory());
//   ...
//     p.advance(dt);
//     if (p.must_write_checkpoint()) {               // after a completed window
//       write_state(p.checkpoint_directory());
//       p.checkpoint_written();
//     }
//
// A restarted participant begins at the window after the checkpoint's, with
// the fields it had received then; it writes no initial data.
namespace cosim {

// Where to reach the coupler; given to a participant on its command line by
// `cosim run` (see add_coupling_options). An empty uri means standalone.
struct CouplingEndpoint {
  std::string uri;          // ipc://..., tcp://127.0.0.1:port, or mpi://
  std::string name;         // the participant's name in the job
  std::string job_id;       // the job this participant was started for
  std::string config_hash;  // hash of the job config it was started for
  // How long to wait for the coupler's welcome; `cosim run` passes its own
  // --connect-timeout, so the coupler, which judges, gives up first.
  double connect_timeout_s = 60.0;
  // The run token `cosim run` hands this process in the COSIM_TOKEN
  // environment variable (never on the command line): taken from there
  // when empty, and the variable removed so the solver's own child
  // processes do not inherit it.
  std::string token = {};
  // Standalone only: run every window twice, going back to its start once
  // (--cosim-repeat-windows): checks a solver's save and restore, since the
  // repeated run must give exactly the results of a plain one.
  bool repeat_windows = false;
  // The participant's directory of a checkpoint to start from
  // (--cosim-restart); empty for a fresh start.
  std::filesystem::path restart = {};
  // The job's `ranks` of a program that starts its solver's processes itself
  // (--cosim-solver-processes, openfoam_adapter's OpenFOAM); 0 when not given.
  int solver_processes = 0;

  bool is_standalone() const { return uri.empty(); }
  // The job's name for this participant, or the solver's own when standalone.
  std::string name_or(std::string fallback) const { return name.empty() ? fallback : name; }
};

// Adds --cosim-endpoint, --cosim-name, --cosim-job, --cosim-config-hash,
// --cosim-connect-timeout, --cosim-repeat-windows, --cosim-restart and
// --cosim-solver-processes to a solver's command line.
void add_coupling_options(CLI::App& app, CouplingEndpoint& endpoint);

// Wall time a participant spent in the coupling, by phase [s].
struct CouplingTimings {
  double waiting = 0.0;        // blocked until the coupler's answer arrived
  double transport = 0.0;      // encoding and sending
  std::size_t windows = 0;     // windows completed
  std::size_t iterations = 0;  // window attempts (windows plus repetitions)
};

class Participant {
 public:
  Participant(std::string name, CouplingEndpoint endpoint);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  const std::string& name() const;
  bool is_coupled() const;

  // Declarations (before initialize).
  void declare_mesh(Mesh mesh);
  // A participant on several ranks (architecture.md §15): each rank declares
  // the part of the mesh it holds, and its fields hold the values of that
  // part, in the part's order. A grid is declared whole with the part; a
  // cloud by this rank's elements. Every rank declares every mesh, even with
  // an empty part, and makes the same calls in the same order.
  void declare_mesh(Mesh mesh, MeshPart part);
  void declare_write(FieldSpec field);
  // `default_value` fills the field until the first exchange, and always
  // when standalone.
  void declare_read(FieldSpec field, double default_value = 0.0);
  // The solver saves its state when must_save_state() and restores it when
  // must_restore_state(): an implicit job can repeat its windows. A job with
  // an implicit scheme refuses a participant that does not declare this.
  void declare_repeatable();
  // The solver writes its state when must_write_checkpoint() and starts from
  // restart_directory() when it is not empty: a job run with
  // --checkpoint-every refuses a participant that does not declare this.
  void declare_checkpointable();
  // On several ranks, each rank writes its part of a checkpoint into its
  // own directory (`rank_<r>/` of the participant's). A solver that can
  // start from the parts of another count of ranks (it reads every part in
  // restart_parts() and keeps what its rank holds now) declares this; one
  // that does not is refused such a restart (exit 2) before its hello.
  void declare_restartable_on_other_ranks();
  // Where the solver reads its state instead of its initial conditions, when
  // it was started from a checkpoint: empty or not from construction on;
  // after initialize(), this rank's part when the checkpoint was written by
  // as many ranks, and the first part (its rank 0's) when not.
  const std::filesystem::path& restart_directory() const;
  // After initialize() on a restart: the directories the checkpoint's ranks
  // wrote, in rank order (one, the participant's directory, for a
  // checkpoint of one rank), and whether they were another count of ranks
  // than this run's (the solver then reads all of restart_parts()).
  const std::vector<std::filesystem::path>& restart_parts() const;
  bool restarts_on_other_ranks() const;

  // Connects to the coupler (handshake: protocol version, job id, config
  // hash), exchanges the initial data (fields written before initialize),
  // and starts the first window. Coupled, the job's start and end time and
  // window apply; standalone, the arguments do and the whole run is one
  // window unless set_standalone_window() says otherwise.
  void initialize(double start_time, double end_time);
  void set_standalone_window(double window);

  double time() const;
  double window_size() const;
  std::size_t window_index() const;  // 1 for the first window
  std::size_t iteration() const;     // attempt at the current window, 1 for the first
  double end_time() const;
  // The longest step that stays inside the current window.
  double max_time_step() const;
  bool is_coupling_ongoing() const;

  // A moving mesh (point cloud) gives its new geometry before the window's
  // last advance; the coupler rebuilds the mappings that involve it.
  void update_mesh(const Mesh& mesh);
  // A cloud's part may change size too (points moved to another rank): the
  // fields on it are resized, a read holds zeros until the next exchange.
  void update_mesh(const Mesh& mesh, MeshPart part);

  // State fields: the last values written in a window are sent at its end.
  // Integral fields: write the rate before every advance(dt); the window's
  // time integral is sent.
  void write(std::string_view field, std::span<const double> values);

  // Ends a step of length dt (<= max_time_step()). When it completes the
  // window, sends the written fields and waits for the partner's. A stop
  // requested by a signal (runtime/stop_request.hpp) throws here, between
  // steps, so the solver ends as on an error and records why.
  void advance(double dt);

  // At the start of a window that may be repeated (after initialize() and
  // after an advance() that completed a window): save the solver's state now.
  bool must_save_state() const;
  // After an advance() that ended a window which must run again: restore the
  // saved state; time() is the window's start and the reads hold the next
  // iterate.
  bool must_restore_state() const;
  // After an advance() that completed a window for good (every window end of
  // an explicit scheme, a converged one of an implicit scheme): outputs due
  // may be written.
  bool is_window_complete() const;
  // After an advance() that completed a window at whose end the job takes a
  // checkpoint: write the solver's state (everything its in-memory save
  // holds, e.g. with cosim/io/state_file.hpp) into checkpoint_directory(),
  // then call checkpoint_written(), which adds this library's own state and
  // tells the coupler.
  bool must_write_checkpoint() const;
  const std::filesystem::path& checkpoint_directory() const;
  void checkpoint_written();

  // State fields: the latest received values at time() + relative_time
  // (0 <= relative_time <= max_time_step()). Explicit schemes: linearly
  // extrapolated from the last two received when the job asks for it.
  // Implicit schemes: the current iterate of the window-end values, or
  // (time_interpolation: linear) interpolated between the converged values at
  // the window's start and that iterate. Integral fields: the whole integral
  // received for the current window.
  void read(std::string_view field, std::span<double> values, double relative_time = 0.0) const;
  std::vector<double> read(std::string_view field) const;
  // Whether read() of a state field depends on relative_time within a window
  // (time_interpolation: linear). A solver then reads at each step, at the
  // step's middle, not once a window at its start (where it would get the
  // window's start values, whatever the partner's iterate).
  bool reads_vary_within_window() const;
  // Integral fields: the share of the window's integral for a step of dt;
  // over a window the shares add up exactly to the integral received.
  void read_increment(std::string_view field, double dt, std::span<double> values);

  // Whether the job sends this read (known from initialize() on; false
  // standalone). An optional read the job leaves out keeps its default.
  bool is_sent(std::string_view field) const;

  // Size of a field's value array (mesh elements x components).
  std::size_t field_size(std::string_view field) const;
  const CouplingTimings& timings() const;

  // Tells the coupler the run ended (normally or not) and releases the
  // transport. Called by the destructor if not before.
  void finalize();
  // Tells the coupler this participant failed, with a reason, then releases.
  // Called while handling a cosim::Error, the error's exit code goes with
  // it (the coupler passes a numerical failure on as its own exit code).
  void abort(std::string_view reason);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosim

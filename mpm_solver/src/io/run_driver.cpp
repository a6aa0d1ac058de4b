#include "mpm/io/run_driver.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/schedule_state.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "mpm/case/load_case.hpp"
#include "mpm/io/grid_snapshot_writer.hpp"
#include "mpm/io/particle_snapshot_writer.hpp"
#include "mpm/io/probe_recorder.hpp"

#ifdef MPM_WITH_MPI
#include <mpi.h>

#include "cosim/io/partitioned_snapshot_writer.hpp"
#include "cosim/runtime/mpi_session.hpp"
#include "mpm/parallel/mpi_grid_partition.hpp"
#endif

namespace mpm {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

template <int Dim>
void record_conserved(cosim::RunSummary& summary, const Totals<Dim>& totals, bool thermal,
                      bool start) {
  const char* per_depth = Dim == 2 ? "/m" : "";
  auto set = [&](const std::string& name, double value, const std::string& unit) {
    const std::string u = unit + per_depth;
    if (start) {
      summary.set_conserved_start(name, value, u);
    } else {
      summary.set_conserved_end(name, value, u);
    }
  };
  set("mass", totals.mass, "kg");
  static constexpr const char* axes[] = {"x", "y", "z"};
  for (int d = 0; d < Dim; ++d)
    set(std::string("momentum_") + axes[d], totals.momentum[d], "kg m/s");
  set("kinetic_energy", totals.kinetic_energy, "J");
  set("strain_energy", totals.strain_energy, "J");
  set("gravitational_energy", totals.gravitational_energy, "J");
  set("contact_dissipation", totals.contact_dissipation, "J");
  set("boundary_dissipation", totals.boundary_dissipation, "J");
  set("external_work", totals.external_work, "J");
  set("plastic_dissipation", totals.plastic_dissipation, "J");
  // Kinetic + strain + gravitational energy plus what left through
  // dissipation, minus the work put in: constant for a consistent scheme.
  set("energy_balance",
      totals.kinetic_energy + totals.strain_energy + totals.gravitational_energy +
          totals.contact_dissipation + totals.boundary_dissipation + totals.plastic_dissipation -
          totals.external_work,
      "J");
  if (!thermal) return;
  // sum m c T, the heat put in by sources (coupling) and through
  // fixed-temperature faces, and their balance, constant to round-off.
  set("thermal_energy", totals.thermal_energy, "J");
  set("external_heat", totals.external_heat, "J");
  set("heat_through_faces", totals.heat_through_faces, "J");
  set("thermal_energy_balance",
      totals.thermal_energy - totals.external_heat - totals.heat_through_faces, "J");
}

nlohmann::json case_section(const CaseDescription& c) {
  nlohmann::json bodies = nlohmann::json::array();
  std::size_t particles = 0;
  for (const auto& b : c.bodies) {
    bodies.push_back(
        {{"name", b.name},
         {"particles", b.positions.size()},
         {"material",
          b.material >= 0 ? c.material_names[static_cast<std::size_t>(b.material)] : "rigid"}});
    particles += b.positions.size();
  }
  std::vector<int> cells(c.grid.cells.begin(), c.grid.cells.begin() + c.dimension);
  return {{"name", c.name},
          {"dimension", c.dimension},
          {"shape", std::string(to_string(c.shape))},
          {"scheme", c.scheme == UpdateScheme::usl ? "usl" : "musl"},
          {"grid_cells", cells},
          {"heat_conduction", c.thermal.enabled},
          {"particles", particles},
          {"bodies", bodies},
          {"end_time_s", c.time.end_time}};
}

// What the loop carries besides the solver: when the next outputs fall due,
// the time of the last snapshot and the range of the stable time step.
struct LoopProgress {
  cosim::OutputSchedule snapshots;
  cosim::OutputSchedule probe_times;
  double last_snapshot = -infinity;
  double min_stable = infinity;
  double max_stable = 0.0;
};

// How a rank of a decomposed run (issue 27) joins the others: its part of
// the grid, and the particle snapshots the ranks write together.
template <int Dim>
struct RunRanks {
  std::shared_ptr<GridPartition<Dim>> partition;
  std::function<std::unique_ptr<cosim::PointCloudSink>()> particle_snapshots;
  // The grid snapshots the ranks write together (output.grid).
  std::function<GridSnapshotWriter<Dim>(const Grid<Dim>&)> grid_snapshots;
  // The points of the fullest rank over the mean, and new cuts when that
  // passes the threshold (true: the solver must repartition); collective.
  std::function<double(const Particles<Dim>&)> imbalance;
  std::function<bool(const Particles<Dim>&)> rebalance;
  // Whether this rank writes the tables (probes.csv): rank 0.
  bool writes_tables = true;
  // This rank and the count of ranks.
  int rank = 0;
  int size = 1;
};

template <int Dim>
class CaseRun {
 public:
  CaseRun(const CaseDescription& description, const RunOptions& options, cosim::RunSummary& summary,
          std::unique_ptr<StepObserver<Dim>> observer, RunRanks<Dim> ranks = {})
      : options_(options),
        summary_(summary),
        observer_(std::move(observer)),
        ranks_(std::move(ranks)),
        solver_(description, ranks_.partition),
        end_time_(description.time.end_time),
        min_time_step_(description.time.min_time_step),
        progress_{cosim::OutputSchedule(description.output.every, end_time_),
                  cosim::OutputSchedule(description.output.probe_every > 0.0
                                            ? description.output.probe_every
                                            : description.output.every,
                                        end_time_)},
        tolerance_(1e-10 * end_time_) {}

  void run() {
    try {
      {
        auto scope = summary_.phases().measure("setup");
        if (observer_) observer_->initialize(solver_);
        // The snapshots' displacements are from the case's initial positions.
        open_outputs();
        if (restarts()) read_checkpoint();
      }
      record_conserved(summary_, solver_.totals(), solver_.conducts_heat(), true);
      solver_.check_state();
      if (!restarts()) {
        hold_snapshot();
        hold_probes();
        write_held_outputs();
      }
      summary_.write();
      loop();
      finish_outputs();
      if (observer_) observer_->finalize();
    } catch (const std::exception& e) {
      // On a rank of a decomposed run the others may be stepping still: no
      // collective sums now (MpiSession::finish ends them).
      record_end(/*together=*/!ranks_.partition);
      if (observer_) observer_->abort(e.what());
      throw;
    }
    record_end(/*together=*/true);
    spdlog::info("completed: t = {:.6g} s in {} steps; {} particle snapshots", solver_.time(),
                 solver_.step_count(), particles_->snapshots_written());
  }

 private:
  void open_outputs() {
    if (ranks_.particle_snapshots) {
      particles_.emplace(ranks_.particle_snapshots(), solver_);
    } else {
      particles_.emplace(options_.output, solver_);
    }
    if (!solver_.description().probes.empty())
      probes_.emplace(options_.output / "probes.csv", solver_, sum_over_ranks(),
                      ranks_.writes_tables);
    if (solver_.description().output.grid) {
      if (GridSnapshotWriter<Dim>::supports(solver_.description().shape)) {
        if (ranks_.grid_snapshots) {
          grid_.emplace(ranks_.grid_snapshots(solver_.grid()));
        } else {
          grid_.emplace(options_.output, solver_.grid());
        }
      } else {
        spdlog::warn(
            "output.grid: no grid snapshots for the {} shape (its grid values are B-spline "
            "control points, not nodal values)",
            to_string(solver_.description().shape));
      }
    }
  }

  bool ongoing() const {
    if (observer_) return observer_->is_ongoing();
    return solver_.time() < end_time_ - tolerance_;
  }

  void loop() {
    using Clock = std::chrono::steady_clock;
    auto last_progress = Clock::now();
    std::size_t steps_at_progress = solver_.step_count();
    while (ongoing()) {
      // A stop asked for by a signal ends the run here, between steps, as an
      // error does: the summary says why (coupled, the participant checks too).
      cosim::runtime::throw_if_stop_requested();
      if (observer_ && observer_->must_save_state()) save_window_start();
      const double t = solver_.time();
      const double stable = solver_.stable_time_step();
      if (!(stable >= min_time_step_))
        throw cosim::NumericalError(fmt::format(
            "the stable time step {:.4g} s fell below time.min_time_step = {:.4g} s at t = {:.9g} "
            "s (step {})",
            stable, min_time_step_, t, solver_.step_count()));
      double dt = stable;
      if (observer_) {
        dt = std::min(dt, observer_->max_time_step());
      } else {
        dt = std::min(dt, end_time_ - t);
      }
      const double next_output = std::min(progress_.snapshots.next(), progress_.probe_times.next());
      if (next_output > t + tolerance_) dt = std::min(dt, next_output - t);
      {
        auto scope = summary_.phases().measure("advance");
        solver_.step(dt);
        ++steps_taken_;
        if (observer_) observer_->after_step(solver_, dt);
      }
      if (observer_ && observer_->must_restore_state()) {
        restore_window_start();
        continue;
      }
      progress_.min_stable = std::min(progress_.min_stable, stable);
      progress_.max_stable = std::max(progress_.max_stable, stable);

      const double now = solver_.time();
      const bool snapshot = progress_.snapshots.due(now, tolerance_);
      const bool probe = progress_.probe_times.due(now, tolerance_);
      const bool check = solver_.step_count() % static_cast<std::size_t>(options_.check_every) == 0;
      if (snapshot || probe || check) solver_.check_state();
      if (check && ranks_.rebalance) balance_due_ = true;
      if (snapshot) hold_snapshot();
      if (probe) hold_probes();
      // Inside a window that may run again, outputs and progress wait for its end.
      if (window_may_repeat_ && !observer_->is_window_complete()) continue;
      window_may_repeat_ = false;
      write_held_outputs();
      // The cuts move only where no window may run again (its start's points
      // are each rank's by the cuts they had then), after the held grid
      // snapshots are written by the ranks that held them.
      if (balance_due_) {
        balance_due_ = false;
        balance_ranks();
      }
      if (observer_ && observer_->must_write_checkpoint()) write_checkpoint();

      const auto wall = Clock::now();
      const double since = std::chrono::duration<double>(wall - last_progress).count();
      if (since >= options_.progress_interval_s) {
        spdlog::info("t = {:.6g} s ({:.1f}%), dt = {:.3g} s, step {}, {:.0f} steps/s", now,
                     100.0 * now / end_time_, dt, solver_.step_count(),
                     static_cast<double>(solver_.step_count() - steps_at_progress) / since);
        last_progress = wall;
        steps_at_progress = solver_.step_count();
        summary_.set_steps(static_cast<std::int64_t>(solver_.step_count()));
        summary_.set_progress(now, end_time_);
        summary_.write();
      }
    }
  }

  // On a rank of a decomposed run: the sum of its values and the others'.
  ProbeRecorder<Dim>::SumOverRanks sum_over_ranks() const {
    if (!ranks_.partition) return {};
    return [partition = ranks_.partition](std::span<double> values) { partition->sum(values); };
  }

  // The points' balance over the ranks, measured; new cuts when it is off.
  void balance_ranks() {
    imbalance_max_ = std::max(imbalance_max_, ranks_.imbalance(solver_.particles()));
    if (!ranks_.rebalance(solver_.particles())) return;
    solver_.repartition();
    ++rebalances_;
    spdlog::info("t = {:.6g} s: the cuts moved to balance the points (now {:.3f} of the mean)",
                 solver_.time(), ranks_.imbalance(solver_.particles()));
  }

  bool restarts() const { return observer_ && !observer_->restart_directory().empty(); }

  // The run's part of a coupled checkpoint (architecture.md §14): the
  // solver's state and the loop's progress, as save_window_start() copies
  // them.
  static constexpr const char* state_file = "state.h5";
  static constexpr const char* state_kind = "mpm_solver";
  static constexpr std::int64_t state_version = 1;

  void write_checkpoint() {
    auto scope = summary_.phases().measure("checkpoint");
    cosim::StateFileWriter out(observer_->checkpoint_directory() / state_file, state_kind,
                               state_version);
    out.integer("dimension", Dim);
    solver_.write_state(out);
    cosim::write_schedule(out, "run.snapshots", progress_.snapshots);
    cosim::write_schedule(out, "run.probe_times", progress_.probe_times);
    out.number("run.last_snapshot", progress_.last_snapshot);
    out.number("run.min_stable", progress_.min_stable);
    out.number("run.max_stable", progress_.max_stable);
    out.commit();
    observer_->checkpoint_written();
  }

  // Each rank of a decomposed run wrote its part; they are read whatever
  // count of ranks wrote them (Solver::read_state).
  void read_checkpoint() {
    std::vector<std::unique_ptr<cosim::StateFileReader>> files;
    std::vector<const cosim::StateFileReader*> parts;
    for (const auto& directory : observer_->restart_parts()) {
      files.push_back(std::make_unique<cosim::StateFileReader>(directory / state_file, state_kind,
                                                               state_version));
      parts.push_back(files.back().get());
    }
    const cosim::StateFileReader& in = *files.at(0);
    if (in.integer("dimension") != Dim)
      throw cosim::InputError(fmt::format("{}: a {}D state, the case is {}D", in.file().string(),
                                          in.integer("dimension"), Dim));
    solver_.read_state(parts, ranks_.rank, ranks_.size);
    cosim::read_schedule(in, "run.snapshots", progress_.snapshots);
    cosim::read_schedule(in, "run.probe_times", progress_.probe_times);
    progress_.last_snapshot = in.number("run.last_snapshot");
    progress_.min_stable = in.number("run.min_stable");
    progress_.max_stable = in.number("run.max_stable");
    spdlog::info("restarted from {} at t = {:.9g} s (step {})",
                 observer_->restart_directory().string(), solver_.time(), solver_.step_count());
  }

  // The start of a window the observer may run again: the solver's state and
  // the loop's, in buffers that keep their capacity from window to window.
  void save_window_start() {
    auto scope = summary_.phases().measure("save_restore");
    solver_.save(saved_solver_);
    saved_progress_ = progress_;
    window_may_repeat_ = true;
    ++saves_;
  }

  void restore_window_start() {
    auto scope = summary_.phases().measure("save_restore");
    if (!saved_progress_)
      throw cosim::Error(cosim::ExitCode::internal_error,
                         "asked to repeat a window whose start was not saved");
    solver_.restore(saved_solver_);
    progress_ = *saved_progress_;
    particles_->drop_held();
    if (grid_) grid_->drop_held();
    if (probes_) probes_->drop_held();
    ++restores_;
  }

  void hold_snapshot() {
    auto scope = summary_.phases().measure("output");
    particles_->hold(solver_);
    if (grid_) grid_->hold(solver_.time(), solver_.grid());
    progress_.last_snapshot = solver_.time();
    progress_.snapshots.passed(solver_.time(), tolerance_);
  }

  void hold_probes() {
    if (probes_) {
      auto scope = summary_.phases().measure("output");
      probes_->hold(solver_);
    }
    progress_.probe_times.passed(solver_.time(), tolerance_);
  }

  void write_held_outputs() {
    const bool snapshot = particles_->held() > 0;
    if (!snapshot && !(probes_ && probes_->held() > 0)) return;
    auto scope = summary_.phases().measure("output");
    particles_->write_held();
    if (grid_) grid_->write_held();
    if (probes_) probes_->write_held();
    if (snapshot) {
      summary_.set_steps(static_cast<std::int64_t>(solver_.step_count()));
      summary_.write();
    }
  }

  // A coupled run may end before or after the case's end time.
  void finish_outputs() {
    solver_.check_state();
    if (solver_.time() > progress_.last_snapshot + tolerance_) {
      hold_snapshot();
      write_held_outputs();
    }
  }

  // `together`: every rank of a decomposed run is here, so the totals can
  // be summed over them.
  void record_end(bool together) noexcept {
    try {
      if (together) record_conserved(summary_, solver_.totals(), solver_.conducts_heat(), false);
      const auto steps = solver_.step_count();
      summary_.set_steps(static_cast<std::int64_t>(steps));
      const double advance = summary_.phases().seconds("advance");
      double particles = static_cast<double>(solver_.particles().size());
      if (together && ranks_.partition) {
        ranks_.partition->sum(std::span<double>(&particles, 1));
        // The points of the fullest rank over the mean: the largest measured
        // (at each check) and at the end; and how often the cuts moved.
        const double now = ranks_.imbalance(solver_.particles());
        summary_.set_metric("point_imbalance_max", std::max(imbalance_max_, now), "1");
        summary_.set_metric("point_imbalance_end", now, "1");
        summary_.set_metric("rebalances", static_cast<double>(rebalances_), "1");
      }
      const double updates = static_cast<double>(steps_taken_) * particles;
      summary_.set_metric("simulated_time", solver_.time(), "s");
      summary_.set_metric("particles", particles, "1");
      summary_.set_metric("particle_updates_per_second", advance > 0.0 ? updates / advance : 0.0,
                          "1/s");
      if (steps > 0) {
        summary_.set_metric("stable_time_step_min", progress_.min_stable, "s");
        summary_.set_metric("stable_time_step_max", progress_.max_stable, "s");
      }
      if (particles_)
        summary_.set_metric("snapshots", static_cast<double>(particles_->snapshots_written()), "1");
      if (saves_ > 0) {
        // Windows that may run again: the cost of going back to their start.
        summary_.set_metric("state_saves", static_cast<double>(saves_), "1");
        summary_.set_metric("state_restores", static_cast<double>(restores_), "1");
        summary_.set_metric("save_restore_seconds", summary_.phases().seconds("save_restore"), "s");
        summary_.set_metric("saved_state_bytes", saved_solver_.bytes(), "B");
      }
      if (observer_) {
        nlohmann::json coupling = observer_->summary(together ? ranks_.partition.get() : nullptr);
        if (coupling.contains("windows"))
          summary_.set_windows(coupling["windows"].get<std::int64_t>());
        if (!coupling.is_null()) summary_.set_section("coupling", std::move(coupling));
      }
    } catch (const std::exception& e) {
      spdlog::warn("could not record the end state in summary.json: {}", e.what());
    }
  }

  const RunOptions& options_;
  cosim::RunSummary& summary_;
  std::unique_ptr<StepObserver<Dim>> observer_;
  RunRanks<Dim> ranks_;
  Solver<Dim> solver_;
  double end_time_;
  double min_time_step_;
  LoopProgress progress_;
  double tolerance_;
  std::optional<ParticleSnapshotWriter<Dim>> particles_;
  std::optional<GridSnapshotWriter<Dim>> grid_;
  std::optional<ProbeRecorder<Dim>> probes_;
  // The start of the current window, when it may run again (observer_->must_save_state()).
  SolverState<Dim> saved_solver_;
  std::optional<LoopProgress> saved_progress_;
  bool window_may_repeat_ = false;
  bool balance_due_ = false;     // a check step asked for the points' balance
  std::size_t steps_taken_ = 0;  // those of repeated windows too
  double imbalance_max_ = 0.0;
  std::size_t rebalances_ = 0;
  std::size_t saves_ = 0;
  std::size_t restores_ = 0;
};

template <int Dim>
void run_dimension(const CaseDescription& description, const RunOptions& options,
                   cosim::RunSummary& summary, const StepObserverFactory<Dim>& factory) {
  std::unique_ptr<StepObserver<Dim>> observer;
  if (factory) observer = factory(description);
  std::optional<CaseRun<Dim>> run;
  {
    auto scope = summary.phases().measure("setup");
    run.emplace(description, options, summary, std::move(observer));
  }
  run->run();
}

void run_loaded(const RunOptions& options, const StepObservers& observers,
                cosim::RunSummary& summary) {
  CaseDescription description;
  {
    auto scope = summary.phases().measure("setup");
    description = load_case(options.config);
    summary.set_config(std::filesystem::absolute(options.config), cosim::hash_file(options.config));
    summary.set_section("case", case_section(description));
  }
  const int threads = options.threads >= 0 ? options.threads : description.threads;
  if (threads > 0) omp_set_num_threads(threads);
  std::size_t particles = 0;
  for (const auto& b : description.bodies) particles += b.positions.size();
  spdlog::info("case '{}' ({}): {}D, {} bodies, {} particles, shape {}, {} threads, end time {} s",
               description.name, options.config.string(), description.dimension,
               description.bodies.size(), particles, to_string(description.shape),
               omp_get_max_threads(), description.time.end_time);
  spdlog::info("size: {} (limits.memory_gib {:g})", description.size.describe(),
               description.size.memory_limit_gib);
  summary.set_section("size", description.size.to_json());
  summary.write();
  if (description.dimension == 2) {
    run_dimension<2>(description, options, summary, observers.for_2d);
  } else {
    run_dimension<3>(description, options, summary, observers.for_3d);
  }
}

#ifdef MPM_WITH_MPI
// The cuts move when the fullest rank holds this many times the mean of
// the points (checked every check_every steps).
constexpr double rebalance_threshold = 1.1;

template <int Dim>
void run_decomposed_dimension(const CaseDescription& description, const RunOptions& options,
                              cosim::RunSummary& summary, const std::vector<int>& cuts,
                              MPI_Comm comm, const StepObserverFactory<Dim>& factory) {
  std::size_t points = 0;
  for (const auto& b : description.bodies) points += b.positions.size();
  const auto last = static_cast<Eigen::Index>(Dim - 1);
  const auto partition = std::make_shared<parallel::MpiGridPartition<Dim>>(
      comm, cuts, description.grid.origin[last], description.grid.spacing[last]);
  RunRanks<Dim> ranks;
  ranks.partition = partition;
  ranks.writes_tables = partition->rank() == 0;
  ranks.rank = partition->rank();
  MPI_Comm_size(comm, &ranks.size);
  ranks.particle_snapshots = [&options, points, comm] {
    return std::make_unique<cosim::PartitionedPointCloudWriter>(comm, options.output, "particles",
                                                                "particles", Dim, points);
  };
  ranks.grid_snapshots = [&options, comm](const Grid<Dim>& grid) {
    const cosim::Mesh mesh = GridSnapshotWriter<Dim>::node_mesh(grid);
    const cosim::Index3 extent = std::get<cosim::UniformGrid>(mesh.geometry).extent();
    // The whole grid's nodes along the other directions, the planes along the last.
    const auto block_of = [extent](std::array<int, 2> planes) {
      std::array<cosim::decomposition::Range, 3> block{};
      for (std::size_t d = 0; d < 3; ++d) block[d] = {0, extent[d]};
      block[Dim - 1] = {planes[0], planes[1]};
      return block;
    };
    auto sink = std::make_unique<cosim::PartitionedSnapshotWriter>(
        comm, options.output, "grid", mesh,
        block_of({grid.owned_first_plane, grid.owned_first_plane + grid.owned_planes}));
    cosim::PartitionedSnapshotWriter* writer = sink.get();
    return GridSnapshotWriter<Dim>(
        std::move(sink), grid,
        [writer, block_of](std::array<int, 2> planes) { writer->set_block(block_of(planes)); });
  };
  ranks.imbalance = [partition](const Particles<Dim>& p) { return partition->imbalance(p); };
  ranks.rebalance = [partition](const Particles<Dim>& p) {
    return partition->rebalance(p, rebalance_threshold);
  };
  std::unique_ptr<StepObserver<Dim>> observer;
  if (factory) observer = factory(description);
  std::optional<CaseRun<Dim>> run;
  {
    auto scope = summary.phases().measure("setup");
    run.emplace(description, options, summary, std::move(observer), std::move(ranks));
  }
  run->run();
}

// mpm_solver on N > 1 ranks (issue 27), standalone under `mpirun -np N` or
// a coupled participant on N ranks of an MPMD job (its own ranks:
// mpi.comm()): the grid's cell rows cut into N parts balanced by the seeded
// points; the observers (coupling windows) run on every rank; rank 0 prepares
// the output directory and writes the summary; every rank writes its points
// into each particle snapshot; rank r keeps its own log and summary in
// ranks/rank_<r>/. The job ends with the largest exit code of its ranks; a
// rank that fails while the others still run ends them all
// (cosim::runtime::MpiSession::finish).
int run_decomposed(const RunOptions& options, const cosim::runtime::MpiSession& mpi,
                   const StepObservers& observers) {
  const cosim::runtime::RankOutput mine = cosim::runtime::prepare_rank_output(
      mpi, options.output, options.reuse, options.verbosity, "mpm_solver");
  if (mine.refused != 0) return mine.refused;
  cosim::init_logging(mine.directory, "mpm_solver", mine.verbosity);
  cosim::RunSummary summary(mine.directory, "mpm_solver");
  summary.write();
  const int code = cosim::run_and_finish(summary, [&] {
    CaseDescription description;
    {
      auto scope = summary.phases().measure("setup");
      description = load_case(options.config);
      summary.set_config(std::filesystem::absolute(options.config),
                         cosim::hash_file(options.config));
    }
    std::vector<int> cuts;
    try {
      cuts = parallel::balanced_row_cuts(description, mpi.ranks());
    } catch (const cosim::InputError& e) {
      throw cosim::InputError(
          fmt::format("{}: key 'grid.cells': {}", description.file.string(), e.what()));
    }
    const int threads = options.threads >= 0 ? options.threads : description.threads;
    if (threads > 0) omp_set_num_threads(threads);
    const double imbalance = parallel::row_imbalance(description, cuts);
    nlohmann::json section = case_section(description);
    section["ranks"] = mpi.ranks();
    section["row_cuts"] = cuts;
    section["point_imbalance"] = imbalance;
    summary.set_section("case", section);
    summary.set_section("size", description.size.to_json());
    summary.write();
    spdlog::info(
        "case '{}' ({}): {}D on {} ranks, cell rows cut at {} (points: largest part {:.3f} of "
        "the mean), {} threads each, end time {} s",
        description.name, options.config.string(), description.dimension, mpi.ranks(),
        fmt::join(cuts, ", "), imbalance, omp_get_max_threads(), description.time.end_time);
    spdlog::info("rank {}: cell rows [{}, {})", mpi.rank(),
                 cuts[static_cast<std::size_t>(mpi.rank())],
                 cuts[static_cast<std::size_t>(mpi.rank()) + 1]);
    if (description.dimension == 2) {
      run_decomposed_dimension<2>(description, options, summary, cuts, mpi.comm(),
                                  observers.for_2d);
    } else {
      run_decomposed_dimension<3>(description, options, summary, cuts, mpi.comm(),
                                  observers.for_3d);
    }
  });
  spdlog::default_logger()->flush();
  return mpi.finish(code);
}
#endif

}  // namespace

bool started_on_several_ranks() {
#ifdef MPM_WITH_MPI
  return cosim::runtime::ranks_from_launcher() > 1;
#else
  return false;
#endif
}

int run_decomposed_case(const RunOptions& options, const StepObservers& observers) {
#ifdef MPM_WITH_MPI
  return run_decomposed(options, cosim::runtime::MpiSession(), observers);
#else
  return run_case(options, observers);
#endif
}

int run_mpi_participant(const RunOptions& options, const StepObservers& observers) {
#ifdef MPM_WITH_MPI
  // MPI from the start, to learn this program's ranks (the transport,
  // started later, then shares it).
  const cosim::runtime::MpiSession mpi;
  if (mpi.ranks() > 1) return run_decomposed(options, mpi, observers);
  return mpi.finish_run("mpm_solver", [&] { return run_case(options, observers); });
#else
  return run_case(options, observers);
#endif
}

int run_case(const RunOptions& options, const StepObservers& observers) {
  cosim::prepare_output_directory(options.output, options.reuse);
  cosim::init_logging(options.output, "mpm_solver", options.verbosity);
  cosim::RunSummary summary(options.output, "mpm_solver");
  summary.write();
  return cosim::run_and_finish(summary, [&] { run_loaded(options, observers, summary); });
}

}  // namespace mpm

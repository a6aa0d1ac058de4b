#include "ice/io/run_case.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/held_outputs.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/schedule_state.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "ice/case/load_case.hpp"
#include "ice/case/make_solver.hpp"
#include "ice/coupling/porous_coupling.hpp"
#include "ice/io/run_ranks.hpp"
#include "ice/io/state_output.hpp"
#include "ice/solver/saved_state.hpp"
#include "ice/solver/saved_state_file.hpp"

#ifdef ICE_WITH_MPI
#include "cosim/runtime/mpi_session.hpp"
#include "ice/parallel/decomposed_run.hpp"
#endif

namespace ice {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr const char* cells_mesh = "ice_cells";
constexpr const char* axis_name[] = {"x", "y", "z"};

// What the run carries from step to step besides the solver's state: the
// output times still to come, the step the stability last allowed and the
// summary's tallies. A window that runs again starts from a copy.
struct RunBookkeeping {
  cosim::OutputSchedule snapshots;
  cosim::OutputSchedule gauge_times;
  double free_dt = 0.0;  // the base of the step-growth limit
  std::size_t steps = 0;
  std::size_t rejected = 0;
  long cg_iterations = 0;
  int most_cg_iterations = 0;
  double most_closure = 0.0;
  double min_dt = infinity;
};

template <int Dim>
class CaseRun {
 public:
  using Vector = Eigen::Matrix<double, Dim, 1>;

  CaseRun(const CaseDescription& description, const cosim::SolverCommandLine& options,
          const cosim::CouplingEndpoint& endpoint, cosim::RunSummary& summary, RunRanks<Dim>& ranks)
      : c_(description),
        options_(options),
        summary_(summary),
        ranks_(ranks),
        participant_(endpoint.name_or(description.name), endpoint),
        coupling_(description.coupling),
        run_{.snapshots = {description.output_every, description.end_time},
             .gauge_times = {description.gauge_every, description.end_time},
             .free_dt = description.numerics.initial_time_step},
        saved_run_(run_),
        tolerance_(1e-10 * description.end_time) {}

  void run() {
    try {
      {
        auto scope = summary_.phases().measure("setup");
        build_solver();
        if (participant_.is_coupled()) {
          std::optional<std::pair<cosim::Mesh, cosim::MeshPart>> decomposed;
          if (auto cells = ranks_.coupling_cells(*solver_, cells_mesh))
            decomposed.emplace(std::move(cells->whole), std::move(cells->part));
          coupling_.declare(participant_, *solver_, std::move(decomposed));
        }
        participant_.declare_repeatable();
        participant_.declare_checkpointable();
        participant_.declare_restartable_on_other_ranks();
        if (c_.window > 0.0) participant_.set_standalone_window(c_.window);
        participant_.initialize(0.0, c_.end_time);
        use_petsc_if_asked();  // after the MPI transport, if any, has started MPI
        // Coupled, the job's end time replaces the case's: the schedules end there.
        const double end = participant_.end_time();
        run_.snapshots = cosim::OutputSchedule(c_.output_every, end);
        run_.gauge_times = cosim::OutputSchedule(c_.gauge_every, end);
        tolerance_ = 1e-10 * end;
        if (restarts()) read_checkpoint();
        open_outputs();
      }
      record_conserved(true);
      if (!restarts()) write_outputs(0.0, {});
      summary_.write();
      loop();
      record_conserved(false);
      end_petsc();
      participant_.finalize();
    } catch (const std::exception& e) {
      if (solver_) record_conserved(false);
      end_petsc();
      participant_.abort(e.what());
      throw;
    }
    spdlog::info("completed: t = {:.6g} s in {} steps ({} rejected), {} snapshots",
                 participant_.time(), run_.steps, run_.rejected,
                 snapshots_ ? snapshots_->snapshots_written() : 0);
  }

 private:
  void build_solver() {
    solver_ = ranks_.make_solver(c_);
    const CellGrid<Dim> grid = case_grid<Dim>(c_);
    summary_.set_section(
        "case", {{"name", c_.name},
                 {"dimension", Dim},
                 {"cells", grid.cell_count()},
                 {"ranks", ranks_.ranks()},
                 {"pressure_solver",
                  c_.numerics.pressure_solver == NumericsDescription::PressureSolverKind::petsc ||
                          solver_->linked()
                      ? "petsc"
                      : "builtin"},
                 {"materials", material_names()},
                 {"cfl", c_.numerics.cfl},
                 {"acoustic", c_.numerics.acoustic},
                 {"limiter", std::string(to_string(c_.numerics.limiter))},
                 {"end_time_s", c_.end_time}});
    spdlog::info("case '{}': {}D, {} cells, materials {}, end time {} s", c_.name, Dim,
                 grid.cell_count(), material_names().dump(), c_.end_time);
  }

  // `solver: petsc` on one process.
  void use_petsc_if_asked() {
    if (solver_->linked() ||
        c_.numerics.pressure_solver != NumericsDescription::PressureSolverKind::petsc)
      return;
#ifdef ICE_WITH_MPI
    petsc_.emplace(MPI_COMM_SELF);  // this process alone, even inside an MPMD job
    solver_->use_pressure_solver(parallel::petsc_pressure_on_one_process<Dim>(c_));
#else
    throw cosim::InputError(
        fmt::format("{}: key 'numerics.pressure.solver': petsc needs a build with MPI and PETSc",
                    c_.file.string()));
#endif
  }

  // PETSc ends before the participant, whose MPI transport may end MPI.
  void end_petsc() {
#ifdef ICE_WITH_MPI
    if (!petsc_) return;
    solver_->use_pressure_solver(nullptr);
    petsc_.reset();
#endif
  }

  nlohmann::json material_names() const {
    nlohmann::json names = nlohmann::json::array();
    for (const FluidMaterial& m : c_.materials) names.push_back(m.name);
    return names;
  }

  void open_outputs() {
    if (c_.snapshots)
      snapshots_ =
          ranks_.snapshots(options_.output, "ice", cell_mesh(case_grid<Dim>(c_), cells_mesh));
    if (!c_.gauges.empty() || !c_.wave_gauges.empty()) {
      const auto file = options_.output / "gauges.csv";
      if (const auto decomposed = ranks_.gauge_cells(*solver_))
        gauges_.emplace(file, c_.gauges, *solver_, c_.wave_gauges, *decomposed,
                        ranks_.writes_outputs());
      else
        gauges_.emplace(file, c_.gauges, *solver_, c_.wave_gauges);
    }
    if (!ranks_.writes_outputs()) return;
    steps_csv_.emplace(
        options_.output / "steps.csv",
        std::vector<std::string>{cosim::column_name("time", "s"), cosim::column_name("dt", "s"),
                                 cosim::column_name("cg_iterations", "1"),
                                 cosim::column_name("equilibration_iterations", "1"),
                                 cosim::column_name("volume_closure", "1"),
                                 cosim::column_name("courant", "1")});
  }

  // Each pass is one step; a window that must run again goes back to the
  // state saved at its start, and its outputs wait until it completes.
  void loop() {
    using Clock = std::chrono::steady_clock;
    auto last_progress = Clock::now();
    const bool coupled = participant_.is_coupled();
    // A medium that varies within the window (time_interpolation: linear) is
    // read once a step, at its middle (below); only the first window's start
    // reads it too, to lay the fluids into the pores.
    const bool medium_each_step = coupled && participant_.reads_vary_within_window();
    while (participant_.is_coupling_ongoing()) {
      if (participant_.must_save_state()) save_window_start();
      const double t = participant_.time();
      if (coupled && participant_.window_index() != medium_window_) {
        medium_window_ = participant_.window_index();
        if (medium_window_ == 1 || !medium_each_step) {
          auto scope = summary_.phases().measure("porous_medium");
          coupling_.read_medium(participant_, *solver_, medium_window_ == 1);
          // The fluids laid into the pores are the run's starting totals.
          if (medium_window_ == 1) record_conserved(true);
        }
      }
      // The growth limit applies to the last step the stability allowed, not
      // to one cut short by a window end or an output time.
      double limit = solver_->stable_time_step(c_.numerics.cfl, c_.numerics.acoustic);
      limit = std::min(limit, c_.numerics.max_step_growth * run_.free_dt);
      if (c_.numerics.max_time_step > 0.0) limit = std::min(limit, c_.numerics.max_time_step);
      run_.free_dt = limit;
      limit = std::min(limit, participant_.max_time_step());
      const double next_output = std::min(
          run_.snapshots.next(), c_.gauge_every > 0.0 ? run_.gauge_times.next() : infinity);
      if (next_output > t + tolerance_) limit = std::min(limit, next_output - t);
      double dt = limit;
      if (medium_each_step) {
        auto scope = summary_.phases().measure("porous_medium");
        coupling_.read_medium(participant_, *solver_, false, 0.5 * dt);
      }
      StepReport report;
      // A step cut short by a window end or an output time may be shorter
      // than min_time_step; the floor is on what the stability allows.
      for (bool refused = false;; refused = true) {
        if (!(dt >= c_.numerics.min_time_step) &&
            (refused || !(run_.free_dt >= c_.numerics.min_time_step))) {
          write_failure_snapshot(t);
          throw cosim::NumericalError(
              fmt::format("the time step {:.4g} s fell below numerics.min_time_step = {:.4g} s at "
                          "t = {:.9g} s (step {})",
                          dt, c_.numerics.min_time_step, t, run_.steps));
        }
        auto scope = summary_.phases().measure("advance");
        report = solver_->advance(dt);
        if (report.accepted && coupled) coupling_.exchange_step(participant_, dt, *solver_);
        if (report.accepted) break;
        ++run_.rejected;
        dt *= 0.5 * std::min(1.0, 1.0 / report.courant);
        run_.free_dt = std::min(run_.free_dt, dt);
      }
      ++run_.steps;
      run_.min_dt = std::min(run_.min_dt, dt);
      run_.cg_iterations += report.pressure_iterations;
      run_.most_cg_iterations = std::max(run_.most_cg_iterations, report.pressure_iterations);
      run_.most_closure = std::max(run_.most_closure, report.volume_closure);
      {
        auto scope = summary_.phases().measure("coupling");
        if (coupled && dt >= participant_.max_time_step() - tolerance_) {
          coupling_.write_fields(participant_, *solver_);
        }
        participant_.advance(dt);
      }
      if (participant_.must_restore_state()) {
        restore_window_start();
        continue;
      }
      const double now = participant_.time();
      write_outputs(now, report, dt);
      if (participant_.is_window_complete()) outputs_.release();
      if (participant_.must_write_checkpoint()) write_checkpoint();
      // Inside a window that may run again, the progress line waits for its end.
      if (outputs_.holding()) continue;
      if (Clock::now() - last_progress > std::chrono::seconds(5)) {
        last_progress = Clock::now();
        spdlog::info("t = {:.6g} s / {:.6g} s, step {}, dt = {:.3g} s, CG iterations {}", now,
                     c_.end_time, run_.steps, dt, report.pressure_iterations);
        summary_.set_steps(static_cast<std::int64_t>(run_.steps));
        summary_.set_progress(now, c_.end_time);
        summary_.write();
      }
    }
  }

  bool restarts() const {
    return !participant_.restart_directory().empty();
  }

  // The run's part of a coupled checkpoint (architecture.md §14): the
  // solver's state as save_state() copies it (into the buffer of the window
  // just accepted, which is not needed again) and the run's bookkeeping.
  static constexpr const char* state_file = "state.h5";
  static constexpr const char* state_kind = "ice_fluid";
  static constexpr std::int64_t state_version = 1;

  void write_checkpoint() {
    auto scope = summary_.phases().measure("checkpoint");
    cosim::StateFileWriter out(participant_.checkpoint_directory() / state_file, state_kind,
                               state_version);
    solver_->save_state(saved_solver_);
    write_saved_state(out, saved_solver_);
    cosim::write_schedule(out, "run.snapshots", run_.snapshots);
    cosim::write_schedule(out, "run.gauge_times", run_.gauge_times);
    out.number("run.free_dt", run_.free_dt);
    out.integers("run.tallies",
                 std::array<std::int64_t, 4>{static_cast<std::int64_t>(run_.steps),
                                             static_cast<std::int64_t>(run_.rejected),
                                             run_.cg_iterations, run_.most_cg_iterations});
    out.number("run.most_closure", run_.most_closure);
    out.number("run.min_dt", run_.min_dt);
    const auto block = block_cells();
    for (const auto& [name, ranges] :
         {std::pair{"block.owned", block.owned}, std::pair{"block.stored", block.stored}})
      out.integers(name, std::array{ranges[0].begin, ranges[0].end, ranges[1].begin, ranges[1].end,
                                    ranges[2].begin, ranges[2].end});
    out.commit();
    participant_.checkpoint_written();
  }

  // The cells of the case's grid this process owns and holds.
  cosim::decomposition::StoredBlock block_cells() const {
    if (auto block = ranks_.block()) return *block;
    std::array<cosim::decomposition::Range, 3> whole{};
    for (std::size_t d = 0; d < 3; ++d)
      whole[d] =
          cosim::decomposition::Range{0, d < static_cast<std::size_t>(Dim) ? c_.cells[d] : 1};
    return {whole, whole, 1};
  }

  // The solver's state from the blocks of a checkpoint written on another
  // count of ranks, joined into this process's block.
  void read_blocks_of_checkpoint() {
    using cosim::decomposition::Range;
    std::vector<std::unique_ptr<cosim::StateFileReader>> files;
    std::vector<const cosim::StateFileReader*> parts;
    std::vector<cosim::decomposition::StoredBlock> written;
    for (const auto& directory : participant_.restart_parts()) {
      files.push_back(std::make_unique<cosim::StateFileReader>(directory / state_file, state_kind,
                                                               state_version));
      parts.push_back(files.back().get());
      std::vector<std::int64_t> owned, stored;
      files.back()->integers("block.owned", 6, owned);
      files.back()->integers("block.stored", 6, stored);
      cosim::decomposition::StoredBlock b;
      for (std::size_t d = 0; d < 3; ++d) {
        b.owned[d] = Range{owned[2 * d], owned[2 * d + 1]};
        b.stored[d] = Range{stored[2 * d], stored[2 * d + 1]};
      }
      written.push_back(b);
    }
    std::array<std::int64_t, 3> grid{1, 1, 1};
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) grid[d] = c_.cells[d];
    read_saved_state<Dim>(parts, written, grid, block_cells(), saved_solver_);
  }

  void read_checkpoint() {
    // On another count of ranks the run's bookkeeping is the first part's.
    const cosim::StateFileReader in(participant_.restart_directory() / state_file, state_kind,
                                    state_version);
    if (participant_.restarts_on_other_ranks())
      read_blocks_of_checkpoint();
    else
      read_saved_state(in, static_cast<std::size_t>(solver_->grid().cell_count()), saved_solver_);
    solver_->restore_state(saved_solver_);
    cosim::read_schedule(in, "run.snapshots", run_.snapshots);
    cosim::read_schedule(in, "run.gauge_times", run_.gauge_times);
    run_.free_dt = in.number("run.free_dt");
    std::vector<std::int64_t> tallies;
    in.integers("run.tallies", 4, tallies);
    run_.steps = static_cast<std::size_t>(tallies[0]);
    run_.rejected = static_cast<std::size_t>(tallies[1]);
    run_.cg_iterations = static_cast<long>(tallies[2]);
    run_.most_cg_iterations = static_cast<int>(tallies[3]);
    run_.most_closure = in.number("run.most_closure");
    run_.min_dt = in.number("run.min_dt");
    spdlog::info("restarted from {} at t = {:.9g} s (step {})",
                 participant_.restart_directory().string(), participant_.time(), run_.steps);
  }

  // At the start of a window that may run again: the solver's state and the
  // run's own are saved, and the window's outputs held until it completes.
  void save_window_start() {
    auto scope = summary_.phases().measure("save_state");
    solver_->save_state(saved_solver_);
    saved_run_ = run_;
    outputs_.hold();
    ++windows_saved_;
  }

  // The window runs again: from the saved state, without its outputs, and
  // with the medium read again (the reads hold the coupler's next iterate).
  void restore_window_start() {
    auto scope = summary_.phases().measure("restore_state");
    solver_->restore_state(saved_solver_);
    run_ = saved_run_;
    outputs_.discard();
    medium_window_ = 0;
  }

  void write_outputs(double t, const StepReport& report, double dt = 0.0) {
    if (gauges_ && (t == 0.0 || c_.gauge_every <= 0.0 || run_.gauge_times.due(t, tolerance_))) {
      const auto row = gauges_->row(t, *solver_, [this](std::span<double> v) { ranks_.sum(v); });
      if (gauges_->writes()) outputs_.append(gauges_->writer(), row);
    }
    if (t > 0.0) run_.gauge_times.passed(t, tolerance_);
    if (t == 0.0 || run_.snapshots.due(t, tolerance_)) {
      auto scope = summary_.phases().measure("output");
      const double row[] = {t,
                            dt,
                            static_cast<double>(report.pressure_iterations),
                            static_cast<double>(report.equilibration_iterations),
                            report.volume_closure,
                            report.courant};
      if (steps_csv_) outputs_.append(*steps_csv_, row);
      if (snapshots_) outputs_.write(*snapshots_, t, ranks_.owned(fields_.fields(*solver_)));
      last_snapshot_time_ = t;
      if (t > 0.0) run_.snapshots.passed(t, tolerance_);
    }
  }

  // The state the steps were refused from (a refused step leaves it as it
  // was) as one more snapshot, so that where and why the run failed can be
  // looked at; not inside a window that may run again (its outputs are held
  // until it converges) nor twice at one time.
  void write_failure_snapshot(double t) {
    if (!snapshots_ || outputs_.holding() || !(t > last_snapshot_time_)) return;
    snapshots_->write(t, ranks_.owned(fields_.fields(*solver_)));
    spdlog::warn("the state at t = {:.9g} s, where the steps were refused, is snapshot {}", t,
                 snapshots_->snapshots_written() - 1);
  }

  void record_conserved(bool start) {
    const auto totals = solver_->totals();
    const bool line = Dim == 1;
    const std::string mass_unit = Dim == 3 ? "kg" : Dim == 2 ? "kg/m" : "kg/m^2";
    const std::string energy_unit = Dim == 3 ? "J" : Dim == 2 ? "J/m" : "J/m^2";
    const std::string momentum_unit = Dim == 3 ? "kg m/s" : Dim == 2 ? "kg/s" : "kg/(m s)";
    auto set = [&](const std::string& name, double value, const std::string& unit) {
      if (start)
        summary_.set_conserved_start(name, value, unit);
      else
        summary_.set_conserved_end(name, value, unit);
    };
    for (std::size_t m = 0; m < totals.size(); ++m) {
      const std::string& name = c_.materials[m].name;
      set("mass_" + name, totals[m].mass, mass_unit);
      for (int d = 0; d < Dim; ++d) {
        set(fmt::format("momentum_{}_{}", axis_name[d], name),
            totals[m].momentum[static_cast<std::size_t>(d)], momentum_unit);
      }
      set("energy_" + name, totals[m].internal_energy + totals[m].kinetic_energy, energy_unit);
    }
    (void)line;
    if (!start) {
      summary_.set_steps(static_cast<std::int64_t>(run_.steps));
      summary_.set_windows(static_cast<std::int64_t>(participant_.timings().windows));
      if (run_.steps > 0) {
        summary_.set_metric("min_time_step", run_.min_dt, "s");
        summary_.set_metric(
            "mean_cg_iterations",
            static_cast<double>(run_.cg_iterations) / static_cast<double>(run_.steps), "1");
      }
      summary_.set_metric("max_cg_iterations", run_.most_cg_iterations, "1");
      summary_.set_metric("rejected_steps", static_cast<double>(run_.rejected), "1");
      summary_.set_metric("max_volume_closure", run_.most_closure, "1");
      record_save_restore_cost();
    }
  }

  // Windows that could run again: the wall time of their saves and restores,
  // in all and per window against the solver's time per attempt at a window.
  void record_save_restore_cost() {
    if (windows_saved_ == 0) return;
    const double seconds =
        summary_.phases().seconds("save_state") + summary_.phases().seconds("restore_state");
    summary_.set_metric("save_restore_seconds", seconds, "s");
    const double advance = summary_.phases().seconds("advance");
    const auto attempts = static_cast<double>(participant_.timings().iterations);
    if (advance > 0.0 && attempts > 0.0) {
      summary_.set_metric("save_restore_share",
                          seconds / static_cast<double>(windows_saved_) / (advance / attempts),
                          "1");
    }
  }

  const CaseDescription& c_;
  const cosim::SolverCommandLine& options_;
  cosim::RunSummary& summary_;
  RunRanks<Dim>& ranks_;
  cosim::Participant participant_;
#ifdef ICE_WITH_MPI
  std::optional<parallel::PetscLibrary> petsc_;  // `solver: petsc` on one process
#endif
  std::unique_ptr<IceSolver<Dim>> solver_;
  PorousCoupling<Dim> coupling_;
  RunBookkeeping run_;
  RunBookkeeping saved_run_;
  SavedIceState<Dim> saved_solver_;
  double tolerance_;
  double last_snapshot_time_ = -infinity;  // of the last snapshot written or held
  std::size_t medium_window_ = 0;          // the window whose porous medium the solver holds
  std::size_t windows_saved_ = 0;
  SnapshotFieldSet<Dim> fields_;
  cosim::HeldOutputs outputs_;
  std::unique_ptr<cosim::SnapshotSink> snapshots_;
  std::optional<GaugeRecorder<Dim>> gauges_;
  std::optional<cosim::TimeSeriesWriter> steps_csv_;
};

template <int Dim>
void run_dimension(const CaseDescription& c, const cosim::SolverCommandLine& options,
                   const cosim::CouplingEndpoint& endpoint, cosim::RunSummary& summary) {
  RunRanks<Dim> one_process;
  CaseRun<Dim> run(c, options, endpoint, summary, one_process);
  run.run();
}

CaseDescription read_case(const cosim::SolverCommandLine& options, cosim::RunSummary& summary) {
  CaseDescription description = [&] {
    auto scope = summary.phases().measure("read_case");
    return load_case(options.config);
  }();
  summary.set_config(options.config, description.config_hash);
  spdlog::info("size: {} (limits.memory_gib {:g})", description.size.describe(),
               description.size.memory_limit_gib);
  summary.set_section("size", description.size.to_json());
  return description;
}

#ifdef ICE_WITH_MPI
template <int Dim>
void run_decomposed_dimension(MPI_Comm comm, const CaseDescription& c,
                              const cosim::SolverCommandLine& options,
                              const cosim::CouplingEndpoint& endpoint, cosim::RunSummary& summary) {
  parallel::DecomposedRun<Dim> part(comm, c);
  const auto& dims = part.decomposition().dims();
  spdlog::info("case '{}': {}D on {} ranks ({} x {} x {} blocks), pressure by PETSc (CG, {})",
               c.name, Dim, part.ranks(), dims[0], dims[1], dims[2],
               c.numerics.petsc_preconditioner);
  const auto& b = part.link().halo().block();
  spdlog::info("rank {}: cells [{}, {}) x [{}, {}) x [{}, {})", part.rank(), b.cells[0].begin,
               b.cells[0].end, b.cells[1].begin, b.cells[1].end, b.cells[2].begin, b.cells[2].end);
  CaseRun<Dim> run(c, options, endpoint, summary, part);
  run.run();
  summary.set_metric("communication_seconds", part.link().communication_seconds(), "s");
  summary.set_metric("halo_values_sent", static_cast<double>(part.link().values_sent()), "1");
}

// ice_fluid on N > 1 ranks: standalone under `mpirun -np N`, or a coupled
// participant on N ranks of an MPMD job (its own ranks: mpi.comm()). Rank 0
// prepares the output directory and writes the tables and the summary;
// every rank writes its block into each snapshot; rank r keeps its own log
// and summary in ranks/rank_<r>/. The run ends with the largest exit code of
// its ranks; a rank that fails while the others still run ends them all
// (cosim::runtime::MpiSession::finish).
int run_decomposed(const cosim::SolverCommandLine& options, const cosim::runtime::MpiSession& mpi) {
  const cosim::runtime::RankOutput mine = cosim::runtime::prepare_rank_output(
      mpi, options.output, options.reuse, options.verbosity, "ice_fluid");
  if (mine.refused != 0) return mine.refused;
  cosim::init_logging(mine.directory, "ice_fluid", mine.verbosity);
  cosim::RunSummary summary(mine.directory, "ice_fluid");
  int code = 0;
  {
    const parallel::PetscLibrary petsc(mpi.comm());
    code = cosim::run_and_finish(summary, [&] {
      const CaseDescription description = read_case(options, summary);
      switch (description.dimension) {
        case 1:
          throw cosim::InputError(
              fmt::format("{}: key 'dimension': a 1D case runs on one "
                          "process; mpirun started {}",
                          description.file.string(), mpi.ranks()));
        case 2:
          run_decomposed_dimension<2>(mpi.comm(), description, options, options.endpoint, summary);
          break;
        default:
          run_decomposed_dimension<3>(mpi.comm(), description, options, options.endpoint, summary);
          break;
      }
    });
  }
  spdlog::default_logger()->flush();
  return mpi.finish(code);
}
#endif

}  // namespace

int run_case(const cosim::SolverCommandLine& options) {
  const cosim::CouplingEndpoint& endpoint = options.endpoint;
#ifdef ICE_WITH_MPI
  if (endpoint.is_standalone() && cosim::runtime::ranks_from_launcher() > 1)
    return run_decomposed(options, cosim::runtime::MpiSession());
  // A participant of an MPMD job: MPI from the start, to learn this program's
  // ranks (the transport, started later, then shares it).
  std::optional<cosim::runtime::MpiSession> mpi;
  if (endpoint.uri == "mpi://") {
    mpi.emplace();
    if (mpi->ranks() > 1) return run_decomposed(options, *mpi);
  }
#endif
  const auto run = [&] {
    cosim::prepare_output_directory(options.output, options.reuse);
    cosim::init_logging(options.output, "ice_fluid", options.verbosity);
    cosim::RunSummary summary(options.output, "ice_fluid");
    return cosim::run_and_finish(summary, [&] {
      const CaseDescription description = read_case(options, summary);
      switch (description.dimension) {
        case 1:
          run_dimension<1>(description, options, endpoint, summary);
          break;
        case 2:
          run_dimension<2>(description, options, endpoint, summary);
          break;
        default:
          run_dimension<3>(description, options, endpoint, summary);
          break;
      }
    });
  };
#ifdef ICE_WITH_MPI
  if (mpi) return mpi->finish_run("ice_fluid", run);
#endif
  return run();
}

}  // namespace ice

#include "swe/io/run_case.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <variant>

#include "cosim/decomposition/block_join.hpp"
#include "cosim/error.hpp"
#include "cosim/fields.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/held_outputs.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/schedule_state.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "swe/case/load_case.hpp"
#include "swe/coupling/bed_traction.hpp"
#include "swe/coupling/extended_free_surface.hpp"
#include "swe/io/gauge_recorder.hpp"
#include "swe/io/run_ranks.hpp"
#include "swe/solver_2d.hpp"
#include "swe/two_phase/two_phase_exchange.hpp"

#ifdef SWE_WITH_MPI
#include "cosim/runtime/mpi_session.hpp"
#include "swe/parallel/decomposed_run.hpp"
#endif

namespace swe {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
const RunRanks one_process;
constexpr const char* cells_mesh = "swe_cells";
constexpr const char* bed_field = cosim::fields::bed_elevation.name;
constexpr const char* traction_field = cosim::fields::bed_traction.name;
constexpr const char* impulse_field = cosim::fields::momentum_exchange_impulse.name;
constexpr const char* surface_field = cosim::fields::free_surface_elevation.name;

struct WaterStats {
  double volume, eta_max, eta_min, speed_max;
};

// Decomposed, every rank's block, reduced over the ranks (collective).
WaterStats water_stats(const Solver& solver, const RunRanks& ranks) {
  const auto h = solver.depth();
  const auto bed = solver.bed();
  const auto qx = solver.discharge_x();
  const auto qy = solver.discharge_y();
  const double dry = solver.physics().dry_depth;
  WaterStats s{solver.totals().volume, -infinity, infinity, 0.0};
  for (std::size_t c = 0; c < h.size(); ++c) {
    if (!(h[c] > dry)) continue;
    s.eta_max = std::max(s.eta_max, h[c] + bed[c]);
    s.eta_min = std::min(s.eta_min, h[c] + bed[c]);
    const double q = qy.empty() ? std::abs(qx[c]) : std::hypot(qx[c], qy[c]);
    s.speed_max = std::max(s.speed_max, q / h[c]);
  }
  std::array<double, 3> largest{s.eta_max, -s.eta_min, s.speed_max};
  ranks.max(largest);
  s = {s.volume, largest[0], -largest[1], largest[2]};
  if (s.eta_max == -infinity) s.eta_max = s.eta_min = std::numeric_limits<double>::quiet_NaN();
  return s;
}

nlohmann::json case_section(const CaseDescription& c, const Solver& solver) {
  return {{"name", c.name},
          {"dimension", c.dimension},
          {"cells", solver.cell_count()},
          {"flux", to_string(c.scheme.flux)},
          {"limiter", to_string(c.scheme.limiter)},
          {"courant", c.scheme.courant},
          {"manning", c.physics.manning},
          {"end_time_s", c.end_time}};
}

// What a run accumulates besides the solver's state: saved with it at the
// start of a window that may run again, and restored when it must.
struct RunProgress {
  std::size_t steps = 0;
  double min_dt = infinity;
  double eta_max = -infinity;  // over the snapshots
  cosim::OutputSchedule snapshots;
  std::optional<cosim::OutputSchedule> gauge_times = std::nullopt;
};

class CaseRun {
 public:
  CaseRun(const CaseDescription& description, const RunOptions& options,
          const cosim::CouplingEndpoint& endpoint, cosim::RunSummary& summary,
          std::unique_ptr<Solver> solver = nullptr, const RunRanks& ranks = one_process)
      : c_(description),
        options_(options),
        summary_(summary),
        solver_(solver ? std::move(solver) : make_solver(description)),
        ranks_(ranks),
        participant_(endpoint.name_or(description.name), endpoint),
        coupling_(description.coupling),
        progress_{.snapshots =
                      cosim::OutputSchedule(description.output_every, description.end_time)},
        tolerance_(1e-10 * description.end_time) {
    if (description.two_phase) make_two_phase();
  }

  void run() {
    try {
      {
        auto scope = summary_.phases().measure("setup");
        nlohmann::json section = case_section(c_, *solver_);
        if (ranks_.ranks() > 1) {
          section["cells"] = static_cast<std::size_t>(c_.grid.cells[0]) *
                             static_cast<std::size_t>(c_.grid.cells[1]);
          section["cells_per_rank"] = solver_->cell_count();
        }
        section["ranks"] = ranks_.ranks();
        summary_.set_section("case", section);
        declare_coupling();
        participant_.declare_repeatable();
        participant_.declare_checkpointable();
        if (solver_->dimension() == 2) participant_.declare_restartable_on_other_ranks();
        if (c_.window > 0.0) participant_.set_standalone_window(c_.window);
        participant_.initialize(0.0, c_.end_time);
        if (!restarts() && participant_.is_coupled() &&
            (c_.coupling.reads_bed || c_.coupling.reads_solid_layer))
          lay_water_over_received_ground();
        record_initial_surface();
        end_time_ = participant_.end_time();
        progress_.gauge_times.emplace(c_.gauge_every, end_time_);
        progress_.snapshots = cosim::OutputSchedule(c_.output_every, end_time_);
        tolerance_ = 1e-10 * end_time_;
        if (restarts()) read_checkpoint();
        open_outputs();
      }
      const Totals start = solver_->totals();
      record_conserved(start, true);
      if (!restarts()) write_outputs(0.0);
      summary_.write();
      loop();
      record_conserved(solver_->totals(), false);
      participant_.finalize();
    } catch (const std::exception& e) {
      // Decomposed, the totals are a collective another rank may never reach.
      if (ranks_.ranks() == 1) record_conserved(solver_->totals(), false);
      participant_.abort(e.what());
      throw;
    }
    spdlog::info("completed: t = {:.6g} s in {} steps ({} snapshots)", participant_.time(),
                 progress_.steps, snapshot_writer_ ? snapshot_writer_->snapshots_written() : 0);
  }

 private:
  void declare_coupling() {
    if (!participant_.is_coupled()) return;
    if (auto decomposed = ranks_.coupling_cells(cells_mesh))
      participant_.declare_mesh(std::move(decomposed->first), std::move(decomposed->second));
    else
      participant_.declare_mesh({cells_mesh, solver_->cells()});
    if (c_.coupling.reads_bed)
      participant_.declare_read(cosim::fields::bed_elevation.on(cells_mesh, 1), 0.0);
    if (c_.coupling.writes_traction) {
      record_initial_surface();
      // a surface of dimension d - 1 under a problem of dimension d
      participant_.declare_write(
          cosim::fields::bed_traction.on(cells_mesh, solver_->dimension() + 1));
      participant_.write(traction_field, bed_traction(*solver_, coupling_));
    }
    if (c_.coupling.reads_solid_layer) {
      namespace f = cosim::fields;
      for (const f::Field* field :
           {&f::column_volume, &f::column_mass, &f::column_momentum, &f::structured_mass})
        participant_.declare_read(field->on(cells_mesh, 2), 0.0);
      cosim::FieldSpec released = f::released_fluid_volume.on(cells_mesh, 2);
      released.optional = true;
      participant_.declare_read(released, 0.0);
    }
    if (c_.coupling.writes_impulse) {
      participant_.declare_write(cosim::fields::momentum_exchange_impulse.on(cells_mesh, 2));
    }
    if (c_.coupling.writes_free_surface) {
      participant_.declare_write(cosim::fields::free_surface_elevation.on(cells_mesh, 2));
      participant_.write(surface_field, free_surface());
    }
  }

  // The water's surface for a mass that floats in it, over dry cells the
  // level of the nearest water; the ground without solids where there is
  // no water at all.
  std::vector<double> free_surface() const {
    if (two_phase_) return extended_free_surface(*solver_, two_phase_->base_bed());
    const auto bed = solver_->bed();
    return extended_free_surface(*solver_, std::vector<double>(bed.begin(), bed.end()));
  }

  // The columns of the coupled mass, summed onto the cells, become the
  // layer the fluid flows over and drags (once a window, at its start).
  void receive_solid_layer() {
    namespace f = cosim::fields;
    const std::size_t n = solver_->cell_count();
    auto read = [&](const f::Field& field, std::size_t per_cell) {
      std::vector<double> values(n * per_cell);
      participant_.read(field.name, values);
      return values;
    };
    const std::vector<double> volume = read(f::column_volume, 1);
    const std::vector<double> mass = read(f::column_mass, 1);
    const std::vector<double> momentum = read(f::column_momentum, 2);
    const std::vector<double> structured = read(f::structured_mass, 1);
    std::vector<double> released;
    if (participant_.is_sent(f::released_fluid_volume.name))
      released = read(f::released_fluid_volume, 1);
    const auto grid = std::get<cosim::UniformGrid>(solver_->cells());
    two_phase_->set_layer(layer_from_columns(
        {volume, mass, momentum, structured, released}, n, grid.spacing[0] * grid.spacing[1],
        participant_.window_size(), two_phase_->parameters().solid_density));
  }

  // The two-phase exchange over the case's bed and initial solid layer (the
  // solver's bed is already bed + h_s: make_solver).
  void make_two_phase() {
    const cosim::Mesh cells{cells_mesh, solver_->cells()};
    std::vector<double> base_bed(cells.size());
    for (std::size_t i = 0; i < base_bed.size(); ++i) {
      const cosim::Vec3 x = cells.position(i);
      base_bed[i] = c_.bed.at(x[0], x[1]);
    }
    two_phase_.emplace(*solver_, c_.two_phase->parameters, c_.two_phase->sources,
                       lay_solid_layer(*c_.two_phase, cells), std::move(base_bed));
    spdlog::info("two-phase: a solid layer under the fluid, drag j = {:g}{}",
                 c_.two_phase->parameters.drag.exponent,
                 c_.two_phase->parameters.virtual_mass ? " with virtual mass" : "");
  }

  // The received bed (the ground without solids) under the fluid: with a
  // solid layer, the fluid's bed is bed + h_s.
  void set_received_bed(const std::vector<double>& bed) {
    if (two_phase_) {
      two_phase_->set_base_bed(bed);
      two_phase_->apply_bed(*solver_);
    } else {
      solver_->set_bed(bed);
    }
  }

  // eta_0 per cell, the reference of BedPressure::excess.
  void record_initial_surface() {
    const auto h = solver_->depth();
    const auto bed = solver_->bed();
    coupling_.initial_surface.resize(h.size());
    for (std::size_t c = 0; c < h.size(); ++c) coupling_.initial_surface[c] = h[c] + bed[c];
  }

  // The bed (and the solid layer) of a coupled run come from the soil: the
  // case's water is laid again over them (a free surface stays a free surface).
  void lay_water_over_received_ground() {
    if (c_.coupling.reads_bed) set_received_bed(participant_.read(bed_field));
    if (c_.coupling.reads_solid_layer) {
      receive_solid_layer();
      two_phase_->apply_bed(*solver_);
    }
    std::vector<double> h, hu, hv;
    c_.initial.lay({cells_mesh, solver_->cells()}, solver_->bed(), h, hu, hv);
    solver_->set_state(h, hu, hv);
    spdlog::info("coupled: water laid over the received {} ({} cells)",
                 c_.coupling.reads_solid_layer ? "ground and solid layer" : "bed",
                 solver_->cell_count());
  }

  // Decomposed, every rank opens the snapshots (written together) and the
  // gauges (sampled by every rank); rank 0 alone writes the tables.
  void open_outputs() {
    if (c_.snapshots)
      snapshot_writer_ = ranks_.snapshots(options_.output, "swe", {cells_mesh, solver_->cells()});
    if (!c_.gauges.empty())
      gauges_.emplace(options_.output / "gauges.csv", c_.gauges, *solver_, ranks_);
    if (!ranks_.writes_outputs()) return;
    water_.emplace(options_.output / "water.csv",
                   std::vector<std::string>{
                       cosim::column_name("time", "s"),
                       cosim::column_name("volume", solver_->dimension() == 1 ? "m^2" : "m^3"),
                       cosim::column_name("eta_max", "m"), cosim::column_name("eta_min", "m"),
                       cosim::column_name("speed_max", "m/s")});
  }

  void loop() {
    using Clock = std::chrono::steady_clock;
    auto last_progress = Clock::now();
    const bool coupled = participant_.is_coupled();
    std::vector<double> bed;
    // A bed that varies within the window is read once a step, at its middle
    // (below); the stable step is then the one over the last step's bed.
    const bool bed_each_step =
        coupled && c_.coupling.reads_bed && participant_.reads_vary_within_window();
    // The window (and attempt) whose solid layer the fluid holds.
    std::pair<std::size_t, std::size_t> layer_window{0, 0};
    while (participant_.is_coupling_ongoing()) {
      if (participant_.must_save_state()) save_window_start();
      const double t = participant_.time();
      if (coupled && c_.coupling.reads_bed && !bed_each_step) {
        auto scope = summary_.phases().measure("bed_update");
        bed.resize(solver_->cell_count());
        participant_.read(bed_field, bed);
        set_received_bed(bed);
      }
      const std::pair window{participant_.window_index(), participant_.iteration()};
      if (coupled && c_.coupling.reads_solid_layer && window != layer_window) {
        auto scope = summary_.phases().measure("solid_layer");
        receive_solid_layer();
        two_phase_->apply_bed(*solver_);
        layer_window = window;
      }
      const double stable = solver_->stable_time_step();
      if (!(stable >= c_.min_time_step))
        throw cosim::NumericalError(
            fmt::format("the stable time step {:.4g} s fell below time.min_time_step = {:.4g} s at "
                        "t = {:.9g} s (step {})",
                        stable, c_.min_time_step, t, progress_.steps));
      double dt = std::min(stable, participant_.max_time_step());
      if (c_.max_time_step > 0.0) dt = std::min(dt, c_.max_time_step);
      const double next_output =
          c_.gauge_every > 0.0 ? std::min(progress_.snapshots.next(), progress_.gauge_times->next())
                               : progress_.snapshots.next();
      if (next_output > t + tolerance_) dt = std::min(dt, next_output - t);
      if (bed_each_step) {
        auto scope = summary_.phases().measure("bed_update");
        bed.resize(solver_->cell_count());
        participant_.read(bed_field, bed, 0.5 * dt);
        set_received_bed(bed);
      }
      {
        auto scope = summary_.phases().measure("advance");
        solver_->step(dt);
      }
      if (two_phase_) {
        auto scope = summary_.phases().measure("two_phase");
        two_phase_->after_step(*solver_, dt);
        if (coupled && c_.coupling.writes_impulse) write_impulse_rate(dt);
      }
      ++progress_.steps;
      progress_.min_dt = std::min(progress_.min_dt, dt);
      const bool window_ends = dt >= participant_.max_time_step() - tolerance_;
      if (coupled && c_.coupling.writes_traction && window_ends) {
        auto scope = summary_.phases().measure("traction");
        participant_.write(traction_field, bed_traction(*solver_, coupling_));
      }
      if (coupled && c_.coupling.writes_free_surface && window_ends) {
        auto scope = summary_.phases().measure("free_surface");
        participant_.write(surface_field, free_surface());
      }
      {
        auto scope = summary_.phases().measure("coupling");
        participant_.advance(dt);
      }
      if (participant_.must_restore_state()) {
        restore_window_start();
        continue;
      }
      if (participant_.is_window_complete()) outputs_.release();
      const double now = participant_.time();
      if (progress_.steps % 64 == 0 || progress_.snapshots.due(now, tolerance_)) check_state(now);
      write_outputs(now);
      if (participant_.must_write_checkpoint()) write_checkpoint();
      if (Clock::now() - last_progress > std::chrono::seconds(5)) {
        last_progress = Clock::now();
        if (ranks_.ranks() > 1) {
          // The water's figures are collective, and the ranks' clocks differ:
          // only the time here.
          spdlog::info("t = {:.6g} s / {:.6g} s, step {}, dt = {:.3g} s", now, end_time_,
                       progress_.steps, dt);
        } else {
          const WaterStats s = water_stats(*solver_, ranks_);
          spdlog::info(
              "t = {:.6g} s / {:.6g} s, step {}, dt = {:.3g} s, eta max {:.6g} m, speed max "
              "{:.4g} m/s",
              now, end_time_, progress_.steps, dt, s.eta_max, s.speed_max);
        }
        summary_.set_steps(static_cast<std::int64_t>(progress_.steps));
        summary_.set_progress(now, end_time_);
        summary_.write();
      }
    }
  }

  // The drag's impulse on the solids over the step just made, as the rate
  // the integral field takes (x and y of a cell side by side).
  void write_impulse_rate(double dt) {
    const auto& jx = two_phase_->impulse_x();
    const auto& jy = two_phase_->impulse_y();
    impulse_rate_.resize(2 * jx.size());
    for (std::size_t c = 0; c < jx.size(); ++c) {
      impulse_rate_[2 * c] = jx[c] / dt;
      impulse_rate_[2 * c + 1] = jy[c] / dt;
      impulse_sent_[0] += jx[c];
      impulse_sent_[1] += jy[c];
    }
    two_phase_->clear_impulse();
    participant_.write(impulse_field, impulse_rate_);
  }

  // A window that may run again starts from a copy of the solver's state and
  // the run's progress, and holds its outputs until it is complete.
  void save_window_start() {
    auto scope = summary_.phases().measure("save_state");
    solver_->save_state();
    if (two_phase_) two_phase_->save_state();
    saved_progress_ = progress_;
    outputs_.hold();
  }

  void restore_window_start() {
    auto scope = summary_.phases().measure("restore_state");
    solver_->restore_state();
    if (two_phase_) two_phase_->restore_state();
    progress_ = *saved_progress_;
    outputs_.discard();
  }

  bool restarts() const { return !participant_.restart_directory().empty(); }

  // The run's part of a coupled checkpoint (architecture.md §14): what
  // save_window_start() copies, and the initial surface the bed pressure's
  // `excess` refers to.
  static constexpr const char* state_file = "state.h5";
  static constexpr const char* state_kind = "swe_fluid";
  static constexpr std::int64_t state_version = 1;

  void write_checkpoint() {
    auto scope = summary_.phases().measure("checkpoint");
    cosim::StateFileWriter out(participant_.checkpoint_directory() / state_file, state_kind,
                               state_version);
    solver_->write_state(out);
    out.integer("run.steps", static_cast<std::int64_t>(progress_.steps));
    out.number("run.min_dt", progress_.min_dt);
    out.number("run.eta_max", progress_.eta_max);
    cosim::write_schedule(out, "run.snapshots", progress_.snapshots);
    cosim::write_schedule(out, "run.gauge_times", *progress_.gauge_times);
    out.numbers("coupling.initial_surface", coupling_.initial_surface);
    if (solver_->dimension() == 2) {
      const auto block = block_cells();
      out.integers("block.cells",
                   std::array{block[0].begin, block[0].end, block[1].begin, block[1].end});
    }
    if (two_phase_) {
      out.numbers("two_phase.velocity_x", two_phase_->layer().velocity_x);
      out.numbers("two_phase.velocity_y", two_phase_->layer().velocity_y);
      out.numbers("two_phase.impulse_x", two_phase_->impulse_x());
      out.numbers("two_phase.impulse_y", two_phase_->impulse_y());
      out.number("two_phase.volume_added", two_phase_->volume_added());
      out.number("two_phase.volume_infiltrated", two_phase_->volume_infiltrated());
    }
    out.commit();
    participant_.checkpoint_written();
  }

  // This process's cells of the whole 2D grid.
  std::array<cosim::decomposition::Range, 3> block_cells() const {
    if (auto block = ranks_.block_cells()) return *block;
    return {cosim::decomposition::Range{0, c_.grid.cells[0]},
            cosim::decomposition::Range{0, c_.grid.cells[1]}, cosim::decomposition::Range{0, 1}};
  }

  // The 2D blocks of a checkpoint written on another count of ranks, joined
  // into this process's block (its cells, and the initial surface); the
  // highest surface is the parts' highest.
  void read_blocks_of_checkpoint() {
    using cosim::decomposition::Range;
    std::vector<std::unique_ptr<cosim::StateFileReader>> files;
    std::vector<const cosim::StateFileReader*> parts;
    std::vector<std::array<Range, 3>> written;
    for (const auto& directory : participant_.restart_parts()) {
      files.push_back(std::make_unique<cosim::StateFileReader>(directory / state_file, state_kind,
                                                               state_version));
      parts.push_back(files.back().get());
      progress_.eta_max = std::max(progress_.eta_max, files.back()->number("run.eta_max"));
      std::vector<std::int64_t> b;
      files.back()->integers("block.cells", 4, b);
      written.push_back({Range{b[0], b[1]}, Range{b[2], b[3]}, Range{0, 1}});
    }
    const std::array<std::int64_t, 3> grid{c_.grid.cells[0], c_.grid.cells[1], 1};
    const auto mine = block_cells();
    dynamic_cast<Solver2d&>(*solver_).read_state(parts, written, grid, mine);
    std::vector<std::vector<double>> surfaces(parts.size());
    std::vector<std::span<const double>> spans;
    std::vector<cosim::decomposition::StoredBlock> from;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      from.push_back(cosim::decomposition::StoredBlock::padded(written[p], {0, 0, 0}));
      parts[p]->numbers("coupling.initial_surface", from.back().size(), surfaces[p]);
      spans.emplace_back(surfaces[p]);
    }
    (void)cosim::decomposition::join_blocks(
        from, spans, grid, cosim::decomposition::StoredBlock::padded(mine, {0, 0, 0}),
        coupling_.initial_surface);
  }

  void read_checkpoint() {
    const bool another_count = participant_.restarts_on_other_ranks();
    // On another count of ranks the run's progress is the first part's.
    const cosim::StateFileReader in(participant_.restart_directory() / state_file, state_kind,
                                    state_version);
    if (!another_count) solver_->read_state(in);
    progress_.steps = static_cast<std::size_t>(in.integer("run.steps"));
    progress_.min_dt = in.number("run.min_dt");
    progress_.eta_max = in.number("run.eta_max");
    if (another_count) read_blocks_of_checkpoint();
    cosim::read_schedule(in, "run.snapshots", progress_.snapshots);
    cosim::read_schedule(in, "run.gauge_times", *progress_.gauge_times);
    if (!another_count)
      in.numbers("coupling.initial_surface", coupling_.initial_surface.size(),
                 coupling_.initial_surface);
    if (two_phase_) {
      TwoPhaseExchange::State state;
      const std::size_t n = solver_->cell_count();
      in.numbers("two_phase.velocity_x", n, state.velocity_x);
      in.numbers("two_phase.velocity_y", n, state.velocity_y);
      in.numbers("two_phase.impulse_x", n, state.impulse_x);
      in.numbers("two_phase.impulse_y", n, state.impulse_y);
      state.added = in.number("two_phase.volume_added");
      state.infiltrated = in.number("two_phase.volume_infiltrated");
      two_phase_->set_state(state);
    }
    spdlog::info("restarted from {} at t = {:.9g} s (step {})",
                 participant_.restart_directory().string(), participant_.time(), progress_.steps);
  }

  // Decomposed, every rank checks its block and all stop together.
  void check_state(double t) const {
    const auto h = solver_->depth();
    const auto q = solver_->discharge_x();
    std::string failure;
    for (std::size_t c = 0; c < h.size() && failure.empty(); ++c)
      if (!std::isfinite(h[c]) || !std::isfinite(q[c]) || h[c] < 0.0)
        failure =
            fmt::format("{}cell {} has depth {} and discharge {} at t = {:.9g} s (step {})",
                        ranks_.ranks() > 1 ? "a block's " : "", c, h[c], q[c], t, progress_.steps);
    if (ranks_.any(!failure.empty()))
      throw cosim::NumericalError(
          failure.empty() ? fmt::format("a cell of another rank's block went bad at t = {:.9g} s "
                                        "(step {}); its log says which",
                                        t, progress_.steps)
                          : failure);
  }

  // Outputs due at t, through outputs_: held while the window may run again.
  // Decomposed, every rank takes part (reductions, collective writes).
  void write_outputs(double t) {
    const bool every_step = c_.gauge_every <= 0.0;
    if (gauges_ && (t == 0.0 || every_step || progress_.gauge_times->due(t, tolerance_)))
      gauges_->record(t, *solver_, outputs_);
    if (t > 0.0) progress_.gauge_times->passed(t, tolerance_);
    if (t == 0.0 || progress_.snapshots.due(t, tolerance_)) {
      auto scope = summary_.phases().measure("output");
      const WaterStats s = water_stats(*solver_, ranks_);
      progress_.eta_max = std::max(progress_.eta_max, s.eta_max);
      const std::array<double, 5> row{t, s.volume, s.eta_max, s.eta_min, s.speed_max};
      if (water_) outputs_.append(*water_, row);
      if (snapshot_writer_) write_snapshot(t);
      if (t > 0.0) progress_.snapshots.passed(t, tolerance_);
    }
  }

  void write_snapshot(double t) {
    const auto h = solver_->depth();
    const auto bed = solver_->bed();
    const auto qx = solver_->discharge_x();
    const auto qy = solver_->discharge_y();
    const double dry = solver_->physics().dry_depth;
    const int dim = solver_->dimension();
    const std::size_t n = h.size();
    eta_.resize(n);
    discharge_.resize(n * static_cast<std::size_t>(dim));
    velocity_.resize(n * static_cast<std::size_t>(dim));
    for (std::size_t c = 0; c < n; ++c) {
      eta_[c] = h[c] + bed[c];
      const std::size_t k = c * static_cast<std::size_t>(dim);
      discharge_[k] = qx[c];
      velocity_[k] = h[c] > dry ? qx[c] / h[c] : 0.0;
      if (dim == 2) {
        discharge_[k + 1] = qy[c];
        velocity_[k + 1] = h[c] > dry ? qy[c] / h[c] : 0.0;
      }
    }
    if (!two_phase_) {
      outputs_.write(*snapshot_writer_, t,
                     {{"h", {h, 1, "m"}},
                      {"eta", {eta_, 1, "m"}},
                      {"bed", {bed, 1, "m"}},
                      {"discharge", {discharge_, dim, "m^2/s"}},
                      {"velocity", {velocity_, dim, "m/s"}}});
      return;
    }
    // Two-phase: `bed` is the ground without solids, `solid_depth` the layer on it.
    const SolidLayer& layer = two_phase_->layer();
    solid_velocity_.resize(2 * n);
    for (std::size_t c = 0; c < n; ++c) {
      solid_velocity_[2 * c] = layer.velocity_x[c];
      solid_velocity_[2 * c + 1] = layer.velocity_y[c];
    }
    outputs_.write(*snapshot_writer_, t,
                   {{"h", {h, 1, "m"}},
                    {"eta", {eta_, 1, "m"}},
                    {"bed", {two_phase_->base_bed(), 1, "m"}},
                    {"solid_depth", {layer.depth, 1, "m"}},
                    {"solid_velocity", {solid_velocity_, 2, "m/s"}},
                    {"discharge", {discharge_, dim, "m^2/s"}},
                    {"velocity", {velocity_, dim, "m/s"}}});
  }

  void record_conserved(const Totals& totals, bool start) {
    const bool line = solver_->dimension() == 1;
    auto set = [&](const std::string& name, double value, const std::string& unit) {
      if (start)
        summary_.set_conserved_start(name, value, unit);
      else
        summary_.set_conserved_end(name, value, unit);
    };
    if (ranks_.writes_outputs()) {  // decomposed, the totals are rank 0's to report
      set("water_volume", totals.volume, line ? "m^2" : "m^3");
      set("momentum_x", c_.physics.density * totals.momentum_x, line ? "kg/s" : "kg m/s");
      if (!line) set("momentum_y", c_.physics.density * totals.momentum_y, "kg m/s");
    }
    if (!start) {
      summary_.set_steps(static_cast<std::int64_t>(progress_.steps));
      summary_.set_windows(static_cast<std::int64_t>(participant_.timings().windows));
      summary_.set_metric("max_free_surface", progress_.eta_max, "m");
      if (progress_.steps > 0) summary_.set_metric("min_time_step", progress_.min_dt, "s");
      const auto& timings = participant_.timings();
      summary_.set_metric("coupling_wait", timings.waiting, "s");
      if (two_phase_) {
        summary_.set_metric("two_phase_volume_added", two_phase_->volume_added(), "m^3");
        summary_.set_metric("two_phase_volume_infiltrated", two_phase_->volume_infiltrated(),
                            "m^3");
        if (c_.coupling.writes_impulse) {
          summary_.set_metric("drag_impulse_sent_x", impulse_sent_[0], "kg m/s");
          summary_.set_metric("drag_impulse_sent_y", impulse_sent_[1], "kg m/s");
        }
      }
    }
  }

  const CaseDescription& c_;
  const RunOptions& options_;
  cosim::RunSummary& summary_;
  std::unique_ptr<Solver> solver_;
  const RunRanks& ranks_;
  cosim::Participant participant_;
  CouplingSpec coupling_;
  RunProgress progress_;
  std::optional<RunProgress> saved_progress_;
  double tolerance_;
  double end_time_ = 0.0;
  cosim::HeldOutputs outputs_;
  std::unique_ptr<cosim::SnapshotSink> snapshot_writer_;
  std::optional<GaugeRecorder> gauges_;
  std::optional<cosim::TimeSeriesWriter> water_;
  std::vector<double> eta_, discharge_, velocity_, solid_velocity_, impulse_rate_;
  std::optional<TwoPhaseExchange> two_phase_;
  std::array<double, 2> impulse_sent_{0.0, 0.0};  // to the solids, in total [kg m/s]
};

// The case, its name and size in the summary, and the threads it asks for.
CaseDescription read_case(const RunOptions& options, cosim::RunSummary& summary) {
  CaseDescription description = [&] {
    auto scope = summary.phases().measure("read_case");
    return load_case(options.config);
  }();
  summary.set_config(options.config, description.config_hash);
  summary.set_section("size", description.size.to_json());
  const int threads = options.threads >= 0 ? options.threads : description.threads;
  if (threads > 0) omp_set_num_threads(threads);
  return description;
}

#ifdef SWE_WITH_MPI
// swe_fluid on N > 1 ranks: standalone under `mpirun -np N`, or a coupled
// participant on N ranks of an MPMD job (its own ranks: mpi.comm()). Rank 0
// prepares the output directory and writes the tables and the summary;
// every rank writes its block into each snapshot; rank r keeps its own log
// and summary in ranks/rank_<r>/. The run ends with the largest exit code
// of its ranks; a rank that fails while the others still run ends them all
// (cosim::runtime::MpiSession::finish).
int run_decomposed(const RunOptions& options, const cosim::CouplingEndpoint& endpoint,
                   const cosim::runtime::MpiSession& mpi) {
  const cosim::runtime::RankOutput mine = cosim::runtime::prepare_rank_output(
      mpi, options.output, options.reuse, options.verbosity, "swe_fluid");
  if (mine.refused != 0) return mine.refused;
  cosim::init_logging(mine.directory, "swe_fluid", mine.verbosity);
  cosim::RunSummary summary(mine.directory, "swe_fluid");
  const int code = cosim::run_and_finish(summary, [&] {
    const CaseDescription description = read_case(options, summary);
    parallel::DecomposedRun part(mpi.comm(), description);
    const auto& b = part.block();
    spdlog::info("case '{}': 2D on {} ranks ({} x {} blocks), {} threads each, end time {} s",
                 description.name, mpi.ranks(), part.decomposition().dims()[0],
                 part.decomposition().dims()[1], omp_get_max_threads(), description.end_time);
    spdlog::info("rank {}: cells [{}, {}) x [{}, {}) of {} x {}", mpi.rank(), b.cells[0].begin,
                 b.cells[0].end, b.cells[1].begin, b.cells[1].end, description.grid.cells[0],
                 description.grid.cells[1]);
    CaseRun run(description, options, endpoint, summary, part.take_solver(), part);
    run.run();
  });
  spdlog::default_logger()->flush();
  return mpi.finish(code);
}
#endif

}  // namespace

int run_case(const RunOptions& options, const cosim::CouplingEndpoint& endpoint) {
#ifdef SWE_WITH_MPI
  if (endpoint.is_standalone() && cosim::runtime::ranks_from_launcher() > 1)
    return run_decomposed(options, endpoint, cosim::runtime::MpiSession());
  // A participant of an MPMD job: MPI from the start, to learn this program's
  // ranks (the transport, started later, then shares it).
  std::optional<cosim::runtime::MpiSession> mpi;
  if (endpoint.uri == "mpi://") {
    mpi.emplace();
    if (mpi->ranks() > 1) return run_decomposed(options, endpoint, *mpi);
  }
#endif
  const auto run = [&] {
    cosim::prepare_output_directory(options.output, options.reuse);
    cosim::init_logging(options.output, "swe_fluid", options.verbosity);
    cosim::RunSummary summary(options.output, "swe_fluid");
    return cosim::run_and_finish(summary, [&] {
      const CaseDescription description = read_case(options, summary);
      spdlog::info("case '{}': {}D, {} threads, end time {} s", description.name,
                   description.dimension, omp_get_max_threads(), description.end_time);
      spdlog::info("size: {} (limits.memory_gib {:g})", description.size.describe(),
                   description.size.memory_limit_gib);
      CaseRun case_run(description, options, endpoint, summary);
      case_run.run();
    });
  };
#ifdef SWE_WITH_MPI
  if (mpi) return mpi->finish_run("swe_fluid", run);
#endif
  return run();
}

}  // namespace swe

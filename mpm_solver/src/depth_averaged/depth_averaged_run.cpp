#include "mpm/depth_averaged/depth_averaged_run.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "cosim/runtime/stop_request.hpp"
#include "mpm/depth_averaged/depth_averaged_case.hpp"
#include "mpm/depth_averaged/depth_averaged_coupling.hpp"

namespace mpm {

namespace {

cosim::Mesh points_mesh(const DepthAveragedParticles& points) {
  cosim::PointCloud cloud;
  cloud.dim = 2;
  cloud.positions.reserve(2 * points.size());
  for (const auto& x : points.position) {
    cloud.positions.push_back(x[0]);
    cloud.positions.push_back(x[1]);
  }
  cloud.volumes = points.volume;
  return {"points", std::move(cloud)};
}

// Where the mass is along the slope and how it moves, for summary.json.
struct MassExtent {
  double front = -std::numeric_limits<double>::infinity();
  double tail = std::numeric_limits<double>::infinity();
  double fastest = 0.0;
  double most_damage = 0.0;
  double least_structured = 1.0;
  double damaged_mass = 0.0;  // of the points whose damage reached 0.5 [kg]
};

MassExtent extent_of(const DepthAveragedSolver& solver) {
  MassExtent e;
  const auto& points = solver.particles();
  for (std::size_t p = 0; p < points.size(); ++p) {
    e.front = std::max(e.front, points.position[p][0]);
    e.tail = std::min(e.tail, points.position[p][0]);
    e.fastest = std::max(e.fastest, points.velocity[p].norm());
    e.most_damage = std::max(e.most_damage, points.damage[p]);
    e.least_structured = std::min(e.least_structured, points.structured_share[p]);
    if (points.damage[p] >= 0.5) e.damaged_mass += points.mass[p];
  }
  return e;
}

class DepthAveragedRun {
 public:
  DepthAveragedRun(DepthAveragedCase description, const RunOptions& options,
                   const cosim::CouplingEndpoint& endpoint, cosim::RunSummary& summary)
      : options_(options),
        summary_(summary),
        end_time_(description.end_time),
        tolerance_(1e-10 * description.end_time),
        snapshots_(description.output_every, description.end_time),
        gauge_times_(
            description.gauge_every > 0.0 ? description.gauge_every : description.output_every,
            description.end_time),
        gauges_(std::move(description.gauges)),
        solver_(std::move(description.settings), std::move(description.materials),
                std::move(description.particles)),
        cells_(ground_cells(solver_.settings().grid)),
        points_writer_(options.output, "points", points_mesh(solver_.particles())),
        ground_writer_(options.output, "ground", cosim::Mesh{"ground", cells_}) {
    if (!endpoint.is_standalone()) {
      participant_.emplace(endpoint.name_or(description.name), endpoint);
      try {
        coupling_.emplace(*participant_, solver_, solver_.settings().confined_fluid_density);
      } catch (const std::invalid_argument& e) {
        throw cosim::InputError(description.inclination_where, "terrain.inclination", e.what());
      }
      coupling_->declare(solver_);
      participant_->initialize(0.0, end_time_);
      end_time_ = participant_->end_time();
      tolerance_ = 1e-10 * end_time_;
      snapshots_ = cosim::OutputSchedule(description.output_every, end_time_);
      gauge_times_ = cosim::OutputSchedule(
          description.gauge_every > 0.0 ? description.gauge_every : description.output_every,
          end_time_);
    }
    if (!gauges_.empty()) {
      std::vector<std::string> columns{cosim::column_name("time", "s")};
      for (const auto& g : gauges_) {
        columns.push_back(cosim::column_name(g.name + "_depth", "m"));
        columns.push_back(cosim::column_name(g.name + "_speed", "m/s"));
      }
      gauge_writer_.emplace(options.output / "gauges.csv", std::move(columns));
    }
  }

  void run() {
    if (coupling_) {
      coupling_->start_window(solver_);  // the water's surface at the start
      window_starts_ = false;
    }
    record_conserved(true);
    write_snapshot();
    write_gauges();
    summary_.write();
    try {
      loop();
      if (coupling_) {
        auto scope = summary_.phases().measure("coupling");
        coupling_->start_window(solver_);  // the drag of the last window
      }
      if (participant_) participant_->finalize();
    } catch (const std::exception& e) {
      record_end();
      if (participant_) participant_->abort(e.what());
      throw;
    }
    record_end();
    spdlog::info("completed: t = {:.6g} s in {} steps; {} points; {} snapshots", solver_.time(),
                 steps_, solver_.particles().size(), points_writer_.snapshots_written());
  }

 private:
  void loop() {
    using Clock = std::chrono::steady_clock;
    auto last_progress = Clock::now();
    while (participant_ ? participant_->is_coupling_ongoing()
                        : solver_.time() < end_time_ - tolerance_) {
      cosim::runtime::throw_if_stop_requested();
      if (coupling_ && window_starts_) {
        auto scope = summary_.phases().measure("coupling");
        coupling_->start_window(solver_);
      }
      const double t = solver_.time();
      double dt = std::min(solver_.stable_time_step(), end_time_ - t);
      if (participant_) dt = std::min(dt, participant_->max_time_step());
      const double next_output = std::min(snapshots_.next(), gauge_times_.next());
      if (next_output > t + tolerance_) dt = std::min(dt, next_output - t);
      {
        auto scope = summary_.phases().measure("advance");
        solver_.step(dt);
      }
      if (coupling_) {
        auto scope = summary_.phases().measure("coupling");
        const bool window_ends = dt >= participant_->max_time_step() - tolerance_;
        coupling_->after_step(solver_, dt, window_ends);
        participant_->advance(dt);
        window_starts_ = participant_->is_window_complete();
      }
      ++steps_;
      point_updates_ += static_cast<double>(solver_.particles().size());
      const double now = solver_.time();
      if (snapshots_.due(now, tolerance_)) write_snapshot();
      if (gauge_times_.due(now, tolerance_)) write_gauges();
      const auto wall = Clock::now();
      if (std::chrono::duration<double>(wall - last_progress).count() >=
          options_.progress_interval_s) {
        spdlog::info("t = {:.6g} s ({:.1f}%), dt = {:.3g} s, step {}, {} points", now,
                     100.0 * now / end_time_, dt, steps_, solver_.particles().size());
        last_progress = wall;
        summary_.set_steps(steps_);
        summary_.set_progress(now, end_time_);
        summary_.write();
      }
    }
  }

  void write_snapshot() {
    auto scope = summary_.phases().measure("output");
    const auto& points = solver_.particles();
    std::vector<double> velocity, depth(points.size()), cohesion(points.size());
    velocity.reserve(2 * points.size());
    for (std::size_t p = 0; p < points.size(); ++p) {
      velocity.push_back(points.velocity[p][0]);
      velocity.push_back(points.velocity[p][1]);
      depth[p] = points.depth(p);
      cohesion[p] = solver_.cohesion(p);
    }
    points_writer_.write(solver_.time(), points_mesh(points),
                         {{"velocity", {velocity, 2, "m/s"}},
                          {"depth", {depth, 1, "m"}},
                          {"mass", {points.mass, 1, "kg"}},
                          {"damage", {points.damage, 1, "1"}},
                          {"structured_share", {points.structured_share, 1, "1"}},
                          {"cohesion", {cohesion, 1, "Pa"}}});

    const std::size_t n = cells_.size();
    std::vector<double> solid_depth(n), bed(n), surface(n), speed(n), fluid_surface;
    const auto& terrain = solver_.settings().terrain;
    for (std::size_t c = 0; c < n; ++c) {
      const auto at = cells_.position(c);
      const Vec<2> x{at[0], at[1]};
      solid_depth[c] = solver_.depth_at(x);
      bed[c] = terrain.bed_elevation(x);
      surface[c] = bed[c] + solid_depth[c];
      speed[c] = solver_.velocity_at(x).norm();
    }
    cosim::SnapshotFields fields{{"solid_depth", {solid_depth, 1, "m"}},
                                 {"bed", {bed, 1, "m"}},
                                 {"solid_surface", {surface, 1, "m"}},
                                 {"solid_speed", {speed, 1, "m/s"}}};
    if (solver_.has_fluid()) {
      fluid_surface.resize(n);
      for (std::size_t c = 0; c < n; ++c) {
        const auto at = cells_.position(c);
        fluid_surface[c] = solver_.fluid_surface_at({at[0], at[1]});
      }
      fields.emplace("fluid_surface", cosim::FieldView{fluid_surface, 1, "m"});
    }
    ground_writer_.write(solver_.time(), fields);
    snapshots_.passed(solver_.time(), tolerance_);
    summary_.set_steps(steps_);
  }

  void write_gauges() {
    if (gauge_writer_) {
      auto scope = summary_.phases().measure("output");
      std::vector<double> row{solver_.time()};
      for (const auto& g : gauges_) {
        row.push_back(solver_.depth_at(g.position));
        row.push_back(solver_.velocity_at(g.position).norm());
      }
      gauge_writer_->append(row);
    }
    gauge_times_.passed(solver_.time(), tolerance_);
  }

  void record_conserved(bool start) {
    const auto& points = solver_.particles();
    const Vec<2> momentum = points.momentum();
    const auto set = [&](const std::string& name, double value, const std::string& unit) {
      if (start)
        summary_.set_conserved_start(name, value, unit);
      else
        summary_.set_conserved_end(name, value, unit);
    };
    set("mass", points.total_mass(), "kg");
    set("momentum_x", momentum[0], "kg m/s");
    set("momentum_y", momentum[1], "kg m/s");
  }

  void record_end() noexcept {
    try {
      record_conserved(false);
      summary_.set_steps(steps_);
      const MassExtent e = extent_of(solver_);
      const Vec<2> centre = solver_.particles().centre_of_mass();
      const double advance = summary_.phases().seconds("advance");
      summary_.set_metric("simulated_time", solver_.time(), "s");
      summary_.set_metric("points", static_cast<double>(solver_.particles().size()), "1");
      summary_.set_metric("point_updates_per_second",
                          advance > 0.0 ? point_updates_ / advance : 0.0, "1/s");
      summary_.set_metric("front_x", e.front, "m");
      summary_.set_metric("tail_x", e.tail, "m");
      summary_.set_metric("centre_of_mass_x", centre[0], "m");
      summary_.set_metric("centre_of_mass_y", centre[1], "m");
      summary_.set_metric("max_speed", e.fastest, "m/s");
      summary_.set_metric("max_damage", e.most_damage, "1");
      summary_.set_metric("damaged_mass_share", e.damaged_mass / solver_.particles().total_mass(),
                          "1");
      summary_.set_metric("min_structured_share", e.least_structured, "1");
      summary_.set_metric("snapshots", static_cast<double>(points_writer_.snapshots_written()),
                          "1");
      double released = 0.0;
      for (double v : solver_.particles().released_fluid) released += v;
      if (!coupling_) summary_.set_metric("fluid_released", released, "m^3");
      if (coupling_) {
        summary_.set_metric("fluid_released", coupling_->fluid_released(), "m^3");
        summary_.set_metric("fluid_released_last_window", coupling_->fluid_released_last_window(),
                            "m^3");
        summary_.set_metric("drag_impulse_received_x", coupling_->impulse_received()[0], "kg m/s");
        summary_.set_metric("drag_impulse_received_y", coupling_->impulse_received()[1], "kg m/s");
        summary_.set_metric("drag_impulse_unplaced", coupling_->impulse_unplaced().cwiseAbs().sum(),
                            "kg m/s");
        summary_.set_windows(static_cast<std::int64_t>(participant_->timings().windows));
        summary_.set_metric("coupling_wait", participant_->timings().waiting, "s");
      }
    } catch (const std::exception& e) {
      spdlog::warn("could not record the end state in summary.json: {}", e.what());
    }
  }

  const RunOptions& options_;
  cosim::RunSummary& summary_;
  double end_time_;
  double tolerance_;
  cosim::OutputSchedule snapshots_;
  cosim::OutputSchedule gauge_times_;
  std::vector<DepthGauge> gauges_;
  DepthAveragedSolver solver_;
  cosim::UniformGrid cells_;
  cosim::SnapshotWriter points_writer_;
  cosim::SnapshotWriter ground_writer_;
  std::optional<cosim::TimeSeriesWriter> gauge_writer_;
  std::optional<cosim::Participant> participant_;
  std::optional<DepthAveragedCoupling> coupling_;
  bool window_starts_ = true;
  std::int64_t steps_ = 0;
  double point_updates_ = 0.0;
};

nlohmann::json case_section(const DepthAveragedCase& c) {
  const auto& g = c.settings.grid;
  return {{"name", c.name},
          {"kind", "depth_averaged_case"},
          {"grid_cells", {g.cells[0], g.cells[1]}},
          {"points", c.particles.size()},
          {"masses", c.mass_names},
          {"inclination_deg", c.settings.terrain.inclination() * 180.0 / std::numbers::pi},
          {"end_time_s", c.end_time}};
}

void run_loaded(const RunOptions& options, const cosim::CouplingEndpoint& endpoint,
                cosim::RunSummary& summary) {
  std::optional<DepthAveragedRun> run;
  {
    auto scope = summary.phases().measure("setup");
    DepthAveragedCase description = load_depth_averaged_case(options.config);
    summary.set_config(std::filesystem::absolute(options.config), cosim::hash_file(options.config));
    summary.set_section("case", case_section(description));
    summary.set_section("size", description.size.to_json());
    const int threads = options.threads >= 0 ? options.threads : description.threads;
    if (threads > 0) omp_set_num_threads(threads);
    spdlog::info(
        "case '{}' ({}): depth-averaged, {} masses, {} points, {} x {} cells, end time {} s",
        description.name, options.config.string(), description.mass_names.size(),
        description.particles.size(), description.settings.grid.cells[0],
        description.settings.grid.cells[1], description.end_time);
    summary.write();
    run.emplace(std::move(description), options, endpoint, summary);
  }
  run->run();
}

}  // namespace

int run_depth_averaged_case(const RunOptions& options, const cosim::CouplingEndpoint& endpoint) {
  cosim::prepare_output_directory(options.output, options.reuse);
  cosim::init_logging(options.output, "mpm_solver", options.verbosity);
  cosim::RunSummary summary(options.output, "mpm_solver");
  summary.write();
  return cosim::run_and_finish(summary, [&] { run_loaded(options, endpoint, summary); });
}

}  // namespace mpm

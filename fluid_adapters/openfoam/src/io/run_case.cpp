#include "openfoam/io/run_case.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <array>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "openfoam/case/existing_case.hpp"
#include "openfoam/case/generated_case.hpp"
#include "openfoam/case/load_case.hpp"
#include "openfoam/foam/control_dict.hpp"
#include "openfoam/foam/field_file.hpp"
#include "openfoam/foam/foam_application.hpp"
#include "openfoam/foam/time_directories.hpp"
#include "openfoam/io/case_mesh.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The fields of interFoam at one time, per cell.
struct FoamFields {
  std::vector<double> alpha_water;
  std::vector<double> p_rgh;
  std::vector<double> p;         // empty at time 0 (the solver writes it)
  std::vector<double> velocity;  // components as the mesh's dimension
};

// The cost of one window [s].
struct WindowTiming {
  double end_time = 0.0;
  double write = 0.0;  // the adapter's files before the start
  ApplicationTiming solver;
  double read = 0.0;  // the fields read back
};

class CaseRun {
 public:
  CaseRun(const CaseDescription& description, const cosim::SolverCommandLine& options,
          cosim::RunSummary& summary)
      : c_(description),
        options_(options),
        summary_(summary),
        case_dir_(options.output / "case"),
        log_dir_(options.output / "openfoam_logs"),
        snapshots_(description.output_every, description.end_time),
        tolerance_(1e-9 * description.time_step) {}

  void run() {
    {
      auto scope = summary_.phases().measure("setup");
      set_up_case();
    }
    FoamFields initial = read_fields(case_dir_ / "0");
    record_water(initial, true);
    write_snapshot(0.0, initial);
    summary_.write();
    double t = 0.0;
    while (t < c_.end_time - tolerance_) {
      const double end = std::min(t + c_.window, c_.end_time);
      FoamFields fields = run_window(t, end);
      t = end;
      if (snapshots_.due(t, tolerance_) || t >= c_.end_time - tolerance_) {
        auto scope = summary_.phases().measure("output");
        write_snapshot(t, fields);
        snapshots_.passed(t, tolerance_);
      }
      if (t >= c_.end_time - tolerance_) record_water(fields, false);
      summary_.set_windows(static_cast<std::int64_t>(windows_.size()));
      summary_.set_steps(steps_);
      summary_.set_section("openfoam_windows", windows_json());
      summary_.write();
    }
    spdlog::info("completed: t = {:.6g} s in {} windows, {} OpenFOAM steps", t, windows_.size(),
                 steps_);
  }

 private:
  void set_up_case() {
    std::vector<std::string> applications{c_.solver, "postProcess"};
    const bool make_mesh = c_.generate || !fs::is_directory(c_.directory / "constant" / "polyMesh");
    if (make_mesh) applications.push_back("blockMesh");
    if (c_.generate) applications.push_back("setFields");
    installation_ = find_installation(applications);
    if (c_.directory.empty()) {
      // A previous run's case in this output directory is replaced.
      fs::remove_all(case_dir_);
      write_generated_case(*c_.generate, case_dir_);
    } else {
      check_existing_case(c_.directory);
      fs::remove_all(case_dir_);
      copy_existing_case(c_.directory, case_dir_);
    }
    fs::create_directories(log_dir_);
    write_controls(0.0, std::min(c_.window, c_.end_time));
    if (make_mesh) run_tool("blockMesh", {});
    if (c_.generate) run_tool("setFields", {});
    mesh_ = read_case_mesh(installation_, case_dir_, log_dir_, c_.generate, "openfoam_cells");
    snapshot_writer_.emplace(options_.output, "openfoam", mesh_.mesh);
    summary_.set_section("case", {{"name", c_.name},
                                  {"solver", c_.solver},
                                  {"cells", mesh_.volumes.size()},
                                  {"case_directory", case_dir_.string()},
                                  {"generated", c_.generate.has_value()},
                                  {"time_step_s", c_.time_step},
                                  {"window_s", c_.window},
                                  {"end_time_s", c_.end_time}});
    spdlog::info("case '{}': {} on {} cells, dt {} s, {} s per start, end time {} s", c_.name,
                 c_.solver, mesh_.volumes.size(), c_.time_step, c_.window, c_.end_time);
  }

  void run_tool(const std::string& name, std::vector<std::string> arguments) {
    auto scope = summary_.phases().measure("preprocessing");
    run_application(installation_, name, std::move(arguments), case_dir_,
                    log_dir_ / (name + ".log"));
  }

  long steps_in(double interval) const { return std::lround(interval / c_.time_step); }

  // The controlDict of a start from `start` to `end`: every field written at `end`.
  void write_controls(double start, double end) {
    write_control_dict(case_dir_, {.application = c_.solver,
                                   .end_time = end,
                                   .time_step = c_.time_step,
                                   .write_every = steps_in(end - start)});
  }

  // One start of the solver from its latest time directory (`start`) to `end`.
  FoamFields run_window(double start, double end) {
    WindowTiming timing;
    timing.end_time = end;
    Clock::time_point phase = Clock::now();
    write_controls(start, end);
    timing.write = seconds_since(phase);
    timing.solver =
        run_application(installation_, c_.solver, {}, case_dir_, log_dir_ / (c_.solver + ".log"));
    phase = Clock::now();
    // The directory the solver wrote at the window's end, found by its time
    // (OpenFOAM lengthens a name that two times would share).
    const auto latest = latest_time_directory(case_dir_);
    if (!latest || std::abs(latest->time - end) > tolerance_) {
      throw cosim::Error(
          cosim::ExitCode::participant_failed,
          fmt::format("OpenFOAM's {} ended without writing the time directory of t = {} s ({} "
                      "in {}; its latest is {}; case kept for inspection)",
                      c_.solver, end, time_name(end, time_precision), case_dir_.string(),
                      latest ? latest->name : "none"));
    }
    FoamFields fields = read_fields(case_dir_ / latest->name);
    timing.read = seconds_since(phase);
    if (!c_.keep_time_directories) {
      const std::array<std::string, 2> keep{"0", latest->name};
      remove_time_directories_except(case_dir_, keep);
    }
    steps_ += steps_in(end - start);
    summary_.phases().add("adapter_write", timing.write);
    summary_.phases().add("openfoam_startup", timing.solver.startup);
    summary_.phases().add("openfoam_stepping", timing.solver.stepping);
    summary_.phases().add("field_read", timing.read);
    windows_.push_back(timing);
    return fields;
  }

  FoamFields read_fields(const fs::path& directory) const {
    const std::size_t cells = mesh_.volumes.size();
    FoamFields f;
    f.alpha_water = read_internal_field(directory / "alpha.water", FieldType::scalar, cells);
    f.p_rgh = read_internal_field(directory / "p_rgh", FieldType::scalar, cells);
    if (fs::exists(directory / "p"))
      f.p = read_internal_field(directory / "p", FieldType::scalar, cells);
    const std::vector<double> u = read_internal_field(directory / "U", FieldType::vector, cells);
    const auto dim = static_cast<std::size_t>(mesh_.mesh.dimension());
    f.velocity.resize(cells * dim);
    for (std::size_t c = 0; c < cells; ++c) {
      for (std::size_t d = 0; d < dim; ++d) f.velocity[c * dim + d] = u[3 * c + d];
    }
    return f;
  }

  void write_snapshot(double t, const FoamFields& f) {
    cosim::SnapshotFields fields{{"alpha_water", {f.alpha_water, 1, "1"}},
                                 {"p_rgh", {f.p_rgh, 1, "Pa"}},
                                 {"velocity", {f.velocity, mesh_.mesh.dimension(), "m/s"}}};
    if (!f.p.empty()) fields.emplace("pressure", cosim::FieldView{f.p, 1, "Pa"});
    snapshot_writer_->write(t, fields);
  }

  // The water's volume sum alpha V (and mass with a generated case's
  // density); per unit depth in 2D.
  void record_water(const FoamFields& f, bool start) {
    double volume = 0.0;
    for (std::size_t c = 0; c < f.alpha_water.size(); ++c) {
      volume += f.alpha_water[c] * mesh_.volumes[c];
    }
    const bool plane = c_.generate && c_.generate->dimension == 2;
    if (plane) volume /= c_.generate->upper[2] - c_.generate->origin[2];
    const auto set = [&](const std::string& name, double value, const std::string& unit) {
      if (start)
        summary_.set_conserved_start(name, value, unit);
      else
        summary_.set_conserved_end(name, value, unit);
    };
    set("volume_water", volume, plane ? "m^2" : "m^3");
    if (c_.generate) set("mass_water", volume * c_.generate->water.density, plane ? "kg/m" : "kg");
  }

  nlohmann::json windows_json() const {
    nlohmann::json w = {{"end_time_s", nlohmann::json::array()},
                        {"adapter_write_s", nlohmann::json::array()},
                        {"solver_startup_s", nlohmann::json::array()},
                        {"solver_stepping_s", nlohmann::json::array()},
                        {"field_read_s", nlohmann::json::array()}};
    for (const WindowTiming& t : windows_) {
      w["end_time_s"].push_back(t.end_time);
      w["adapter_write_s"].push_back(t.write);
      w["solver_startup_s"].push_back(t.solver.startup);
      w["solver_stepping_s"].push_back(t.solver.stepping);
      w["field_read_s"].push_back(t.read);
    }
    w["steps_per_window"] = steps_in(c_.window);
    return w;
  }

  const CaseDescription& c_;
  const cosim::SolverCommandLine& options_;
  cosim::RunSummary& summary_;
  fs::path case_dir_;
  fs::path log_dir_;
  cosim::OutputSchedule snapshots_;
  double tolerance_;
  Installation installation_;
  CaseMesh mesh_;
  std::optional<cosim::SnapshotWriter> snapshot_writer_;
  std::vector<WindowTiming> windows_;
  std::int64_t steps_ = 0;
};

}  // namespace

int run_case(const cosim::SolverCommandLine& options) {
  cosim::create_output_directory(options.output);
  cosim::init_logging(options.output, "openfoam_adapter", options.verbosity);
  cosim::RunSummary summary(options.output, "openfoam_adapter");
  return cosim::run_and_finish(summary, [&] {
    const CaseDescription description = [&] {
      auto scope = summary.phases().measure("read_case");
      return load_case(options.config);
    }();
    summary.set_config(options.config, description.config_hash);
    if (!options.endpoint.is_standalone()) {
      throw cosim::InputError(
          "openfoam_adapter runs standalone only so far: coupling with the MPM soil "
          "(MPPICInterFoam with the soil as parcels) is not built yet");
    }
    CaseRun run(description, options, summary);
    run.run();
  });
}

}  // namespace openfoam

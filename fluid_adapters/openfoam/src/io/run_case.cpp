#include "openfoam/io/run_case.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <vector>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/output_schedule.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/io/schedule_state.hpp"
#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "cosim/participant.hpp"
#include "openfoam/case/case_properties.hpp"
#include "openfoam/case/decomposition.hpp"
#include "openfoam/case/existing_case.hpp"
#include "openfoam/case/generated_case.hpp"
#include "openfoam/case/load_case.hpp"
#include "openfoam/cloud/soil_cloud.hpp"
#include "openfoam/foam/control_dict.hpp"
#include "openfoam/foam/field_file.hpp"
#include "openfoam/foam/foam_application.hpp"
#include "openfoam/foam/foam_dictionary.hpp"
#include "openfoam/foam/time_directories.hpp"
#include "openfoam/io/case_layout.hpp"
#include "openfoam/io/case_mesh.hpp"
#include "openfoam/io/cell_neighbours.hpp"
#include "openfoam/io/foam_fields.hpp"
#include "openfoam/io/gauge_recorder.hpp"
#include "openfoam/io/restart_inertia.hpp"
#include "openfoam/io/soil_coupling.hpp"
#include "openfoam/io/soil_exchange_record.hpp"
#include "openfoam/io/window_step_means.hpp"
#include "openfoam/io/window_timing.hpp"
#include "openfoam/porosity/porosity_zones.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

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
    FoamFields fields = read_fields("0");
    write_start_fluid_fraction(fields.alphac);
    record_water(fields, true);
    write_outputs(0.0, fields);
    summary_.write();
    double t = 0.0;
    while (t < c_.end_time - tolerance_) {
      const double end = std::min(t + c_.window, c_.end_time);
      fields = run_window(t, end);
      t = end;
      finish_window(t, fields, t >= c_.end_time - tolerance_);
      summary_.set_progress(t, c_.end_time);
      if (windows_.size() % 20 == 0) summary_.write();
    }
    spdlog::info("completed: t = {:.6g} s in {} windows, {} OpenFOAM steps", t, windows_.size(),
                 steps_);
  }

  // Coupled with the MPM soil: one OpenFOAM start per coupling window, the
  // soil's parcels written into the window's start directory.
  void run_coupled() {
    const bool zones = c_.soil.model == SoilModel::porosity_zones;
    if (!c_.has_cloud() && !zones) {
      throw cosim::InputError(cosim::SourceLocation{c_.file.string(), 0, 0}, "solver",
                              "coupled with a soil the solver must be MPPICInterFoam (the soil "
                              "enters OpenFOAM as its parcels), or interFoam with `soil: {model: "
                              "porosity_zones}`; the case runs " +
                                  c_.solver);
    }
    {
      auto scope = summary_.phases().measure("setup");
      set_up_case();
    }
    SoilCoupling coupling(c_, mesh_, properties_,
                          c_.generate ? CellNeighbours::of_grid(c_.generate->cells)
                                      : CellNeighbours::of_mesh(case_dir_ / "constant" / "polyMesh",
                                                                mesh_.volumes.size()));
    cosim::Participant participant(options_.endpoint.name_or("openfoam"), options_.endpoint);
    // The coupler hears why this participant stopped before it stops the
    // others.
    try {
      exchange_windows(participant, coupling);
    } catch (const std::exception& e) {
      participant.abort(e.what());
      throw;
    }
    participant.finalize();
    spdlog::info(
        "completed: t = {:.6g} s in {} windows, {} OpenFOAM steps; the cloud's momentum on the "
        "water against the drag law's: largest mismatch {:.3g}",
        participant.time(), windows_.size(), steps_,
        soil_record_ ? soil_record_->worst_mismatch() : 0.0);
  }

 private:
  void set_up_case() {
    std::vector<std::string> applications{c_.solver, "postProcess"};
    const bool make_mesh = c_.generate || !fs::is_directory(c_.directory / "constant" / "polyMesh");
    // A user's case has its water set by its own setFieldsDict, if it has one.
    const bool set_fields =
        c_.generate || fs::is_regular_file(c_.directory / "system" / "setFieldsDict");
    if (make_mesh) applications.push_back("blockMesh");
    if (set_fields) applications.push_back("setFields");
    if (!c_.generate) {
      for (const char* tool : {"foamDictionary", "checkMesh", "foamFormatConvert"})
        applications.push_back(tool);
    }
    if (c_.soil.model == SoilModel::porosity_zones) applications.push_back("topoSet");
    if (c_.processes > 1) {
      applications.push_back("decomposePar");
      applications.push_back("mpirun");
    }
    installation_ = find_installation(applications);
    if (c_.directory.empty()) {
      // A previous run's case in this output directory is replaced.
      fs::remove_all(case_dir_);
      write_generated_case(*c_.generate, case_dir_, c_.has_cloud() ? &c_.soil : nullptr);
    } else {
      check_existing_case(c_.directory);
      fs::remove_all(case_dir_);
      copy_existing_case(c_.directory, case_dir_);
    }
    fs::create_directories(log_dir_);
    write_controls(0.0, std::min(c_.window, c_.end_time));
    if (make_mesh) run_tool("blockMesh", {});
    if (c_.generate) {
      properties_ = properties_of(*c_.generate);
    } else {
      auto scope = summary_.phases().measure("preprocessing");
      const DictionaryQuery query{installation_, case_dir_, log_dir_ / "foamDictionary.log"};
      convert_copy_to_ascii(query);
      if (c_.has_cloud()) prepare_cloud_in_copy(query, c_.soil);
      properties_ = read_case_properties(installation_, case_dir_, log_dir_);
    }
    if (set_fields) run_tool("setFields", {});
    mesh_ = read_case_mesh(installation_, case_dir_, log_dir_, c_.generate, properties_,
                           SoilCoupling::mesh_name);
    if (c_.processes > 1) {
      // Decomposed once; the windows then run on the processors' directories.
      const std::array<int, 3> split = c_.split_given ? c_.split : split_of_mesh();
      spdlog::info("OpenFOAM on {} processes, {} x {} x {} blocks", c_.processes, split[0],
                   split[1], split[2]);
      write_decompose_par_dict(case_dir_, c_.processes, split);
      run_tool("decomposePar", {"-force"});
    }
    layout_.emplace(case_dir_, c_.processes, mesh_.volumes.size());
    if (!c_.gauges.empty() || !c_.wave_gauges.empty())
      gauges_.emplace(c_, mesh_, options_.output / "gauges.csv");
    snapshot_writer_.emplace(options_.output, "openfoam", mesh_.mesh);
    summary_.set_section("case", {{"name", c_.name},
                                  {"solver", c_.solver},
                                  {"cells", mesh_.volumes.size()},
                                  {"case_directory", case_dir_.string()},
                                  {"processes", c_.processes},
                                  {"generated", c_.generate.has_value()},
                                  {"dimension", properties_.dimension},
                                  {"water_density_kg/m^3", properties_.water.density},
                                  {"water_viscosity_Pa_s", properties_.water.viscosity},
                                  {"air_density_kg/m^3", properties_.air.density},
                                  {"air_viscosity_Pa_s", properties_.air.viscosity},
                                  {"time_step_s", c_.time_step},
                                  {"window_s", c_.window},
                                  {"end_time_s", c_.end_time}});
    spdlog::info("case '{}': {} on {} cells, dt {} s, {} s per start, end time {} s", c_.name,
                 c_.solver, mesh_.volumes.size(), c_.time_step, c_.window, c_.end_time);
  }

  // The blocks of the simple method for the run's processes (the case's
  // parallel.processes, or the job's `ranks` of this participant).
  std::array<int, 3> split_of_mesh() const {
    try {
      return choose_split(c_.processes, mesh_.centres);
    } catch (const cosim::InputError& e) {
      throw cosim::InputError(
          cosim::SourceLocation{c_.file.string(), 0, 0}, "parallel.processes",
          fmt::format("{} (the processes are the case's parallel.processes or, coupled, the "
                      "job's `ranks` of this participant)",
                      e.what()));
    }
  }

  void run_tool(const std::string& name, std::vector<std::string> arguments) {
    auto scope = summary_.phases().measure("preprocessing");
    run_application(installation_, name, std::move(arguments), case_dir_,
                    log_dir_ / (name + ".log"));
  }

  void exchange_windows(cosim::Participant& participant, SoilCoupling& coupling) {
    FoamFields fields = start_coupling(participant, coupling);
    while (participant.is_coupling_ongoing()) exchange_window(participant, coupling, fields);
  }

  // Window 0: the declarations, the water's initial fields to the soil, the
  // pores the soil leaves the water (MPPICInterFoam sees them from its first
  // start on) and the initial outputs.
  FoamFields start_coupling(cosim::Participant& participant, SoilCoupling& coupling) {
    coupled_ = true;
    coupling.declare(participant);
    participant.declare_repeatable();
    participant.declare_checkpointable();
    FoamFields fields = read_fields("0");
    coupling.write(participant, fields, c_.time_step, 0);
    participant.initialize(0.0, c_.end_time);
    check_window(participant.window_size());
    if (!participant.restart_directory().empty()) {
      read_checkpoint(participant.restart_directory(), coupling, fields);
      soil_record_.emplace(options_.output / "soil_exchange.csv");
      return fields;
    }
    if (c_.soil.model != SoilModel::porosity_zones) {
      fields.alphac = coupling.fluid_fraction(participant);
      write_start_fluid_fraction(fields.alphac);
    }
    record_water(fields, true);
    write_outputs(0.0, fields);
    summary_.write();
    soil_record_.emplace(options_.output / "soil_exchange.csv");
    return fields;
  }

  void check_window(double window) const {
    if (is_whole_number_of_steps(window, c_.time_step)) return;
    throw cosim::InputError(
        cosim::SourceLocation{c_.file.string(), 0, 0}, "time_step",
        fmt::format("the job's window {} s is not a whole number of OpenFOAM time steps of {} s",
                    window, c_.time_step));
  }

  // One coupling window, in order: the soil into OpenFOAM's start, OpenFOAM
  // over the window, the water's fields to the soil, then the window's
  // record and outputs. A window that must run again (implicit coupling)
  // starts over from its start directory, which is kept until the window is
  // complete, and leaves no record or output.
  void exchange_window(cosim::Participant& participant, SoilCoupling& coupling,
                       FoamFields& fields) {
    if (participant.must_save_state()) save_window_start(coupling);
    const double start = participant.time();
    const double end = start + participant.max_time_step();
    write_soil(participant, coupling, fields);
    FoamFields end_fields = run_window(start, end, window_start_.has_value());
    const auto check = send_water(participant, coupling, end_fields, end - start);
    if (participant.must_restore_state()) {
      restore_window_start(coupling, end);
      return;
    }
    fields = std::move(end_fields);
    if (window_start_ && !c_.keep_time_directories && window_start_->directory != "0")
      layout_->remove_time(window_start_->directory);
    soil_record_->record(check, end - start, end, parcels_);
    finish_window(end, fields, !participant.is_coupling_ongoing());
    if (participant.must_write_checkpoint()) write_checkpoint(participant, coupling, fields);
  }

  // The adapter's part of a coupled checkpoint (architecture.md §14): the
  // case's time directory at the window's end (every processor's), the
  // fields read from it as the next window uses them (the step means), the
  // coupling's carried state, and the run's tallies and output schedule.
  static constexpr const char* state_file = "state.h5";
  static constexpr const char* state_kind = "openfoam_adapter";
  static constexpr std::int64_t state_version = 1;

  // The fields' arrays by name (pointers, const when `f` is).
  template <class Fields>
  static auto field_arrays(Fields& f) {
    using Array = std::conditional_t<std::is_const_v<Fields>, const std::vector<double>*,
                                     std::vector<double>*>;
    return std::array<std::pair<const char*, Array>, 6>{{{"alpha_water", &f.alpha_water},
                                                         {"p_rgh", &f.p_rgh},
                                                         {"p", &f.p},
                                                         {"velocity", &f.velocity},
                                                         {"alphac", &f.alphac},
                                                         {"cloud_momentum", &f.cloud_momentum}}};
  }

  void write_checkpoint(cosim::Participant& participant, const SoilCoupling& coupling,
                        const FoamFields& fields) {
    auto scope = summary_.phases().measure("checkpoint");
    const fs::path dir = participant.checkpoint_directory();
    layout_->copy_time_out(layout_->latest()->name, dir / "time");
    cosim::StateFileWriter out(dir / state_file, state_kind, state_version);
    for (const auto& [name, values] : field_arrays(fields))
      if (!values->empty()) out.numbers(std::string("fields.") + name, *values);
    if (const auto carried = coupling.carried_state(); !carried.empty())
      out.numbers("coupling.carried", carried);
    out.integer("run.steps", steps_);
    out.integer("run.windows", static_cast<std::int64_t>(windows_done()));
    out.integer("run.parcels", static_cast<std::int64_t>(parcels_));
    out.integer("run.processes", c_.processes);
    cosim::write_schedule(out, "run.snapshots", snapshots_);
    out.commit();
    participant.checkpoint_written();
  }

  void read_checkpoint(const fs::path& dir, SoilCoupling& coupling, FoamFields& fields) {
    const cosim::StateFileReader in(dir / state_file, state_kind, state_version);
    // The time directory is every processor's of the decomposition it was
    // written with.
    const std::int64_t written_on = in.has("run.processes") ? in.integer("run.processes") : 1;
    if (written_on != c_.processes)
      throw cosim::InputError(fmt::format(
          "{}: the checkpoint holds OpenFOAM's fields decomposed for {} process{}, and this run "
          "has OpenFOAM on {}; restart with the checkpoint's count (the job's `ranks` of this "
          "participant, or the case's parallel.processes)",
          (dir / state_file).string(), written_on, written_on == 1 ? "" : "es", c_.processes));
    layout_->copy_times_in(dir / "time");
    for (const auto& [name, values] : field_arrays(fields))
      *values = in.has(std::string("fields.") + name) ? in.numbers(std::string("fields.") + name)
                                                      : std::vector<double>{};
    coupling.restore(in.has("coupling.carried") ? in.numbers("coupling.carried")
                                                : std::vector<double>{});
    steps_ = in.integer("run.steps");
    windows_before_restart_ = static_cast<std::size_t>(in.integer("run.windows"));
    parcels_ = static_cast<std::size_t>(in.integer("run.parcels"));
    cosim::read_schedule(in, "run.snapshots", snapshots_);
    spdlog::info("restarted from {} at t = {:.9g} s (time directory {})", dir.string(),
                 layout_->latest()->time, layout_->latest()->name);
  }

  std::size_t windows_done() const { return windows_before_restart_ + windows_.size(); }

  // The state a repeated window starts over from: the case's time
  // directories up to the window's start (kept by run_window), the
  // coupling's carried velocity, and the tallies of the windows run.
  struct WindowStart {
    std::string directory;
    std::vector<double> coupling;
    long steps = 0;
    std::size_t windows = 0;
  };

  void save_window_start(const SoilCoupling& coupling) {
    window_start_ =
        WindowStart{layout_->latest()->name, coupling.carried_state(), steps_, windows_.size()};
  }

  // The window's end directory goes, so that OpenFOAM starts again from the
  // window's start directory.
  void restore_window_start(SoilCoupling& coupling, double end) {
    if (!window_start_)
      throw cosim::Error(cosim::ExitCode::internal_error,
                         "openfoam_adapter: asked to repeat a window whose start was not saved");
    if (const auto written = layout_->at(end, tolerance_)) layout_->remove_time(written->name);
    coupling.restore(window_start_->coupling);
    steps_ = window_start_->steps;
    windows_.resize(window_start_->windows);
    ++state_restores_;
    summary_.set_metric("state_restores", static_cast<double>(state_restores_), "1");
  }

  // The soil as MPPICInterFoam's parcels in the start directory, or as the
  // fallback's porosity zones.
  void write_soil(cosim::Participant& participant, SoilCoupling& coupling,
                  const FoamFields& fields) {
    if (c_.soil.model == SoilModel::porosity_zones) {
      write_porosity_zones(coupling.darcy_coefficients(participant));
      return;
    }
    auto scope = summary_.phases().measure("adapter_write");
    const SoilParcels& parcels = coupling.parcels(participant, fields);
    layout_->write_cloud(layout_->latest()->name, parcels, c_.soil.parcel_density);
    parcels_ = parcels.size();
  }

  // The water's fields at the window's end (its step means, window_step_means.hpp)
  // to the soil, and the participant's time to the window's end.
  SoilCoupling::MomentumCheck send_water(cosim::Participant& participant, SoilCoupling& coupling,
                                         FoamFields& fields, double window) {
    auto scope = summary_.phases().measure("coupling");
    const SoilCoupling::MomentumCheck check =
        coupling.write(participant, fields, window, steps_in(window));
    participant.advance(window);
    return check;
  }

  // The fallback's zones for the window: the cells' d into the start
  // directory, topoSet's dictionary and the porosity sources, then topoSet.
  void write_porosity_zones(const std::vector<double>& darcy) {
    const std::vector<PorosityZone> zones = porosity_zones(darcy, c_.soil.zones);
    const std::string start = layout_->latest()->name;
    {
      auto scope = summary_.phases().measure("adapter_write");
      layout_->write_scalar_field(start, darcy_field, "[0 -2 0 0 0 0 0]", darcy);
      cosim::write_file_atomically(case_dir_ / "system" / "topoSetDict", topo_set_dict(zones));
      cosim::write_file_atomically(case_dir_ / "constant" / "fvOptions",
                                   porosity_fv_options(zones));
    }
    parcels_ = static_cast<std::size_t>(
        std::count_if(darcy.begin(), darcy.end(), [](double d) { return d > 0.0; }));
    if (zones.empty()) return;
    auto scope = summary_.phases().measure("topo_set");
    run_application(installation_, "topoSet", {"-time", start}, case_dir_, log_dir_ / "topoSet.log",
                    c_.processes);
  }

  long steps_in(double interval) const { return std::lround(interval / c_.time_step); }

  void finish_window(double t, const FoamFields& fields, bool last) {
    write_outputs(t, fields, last);
    if (last) record_water(fields, false);
    summary_.set_windows(static_cast<std::int64_t>(windows_done()));
    summary_.set_steps(steps_);
    summary_.set_section("openfoam_windows", windows_json(windows_, steps_in(c_.window)));
    if (soil_record_) soil_record_->set_metrics(summary_);
    summary_.write();
  }

  void write_outputs(double t, const FoamFields& fields, bool last = false) {
    if (gauges_) gauges_->record(t, fields);
    if (t == 0.0 || snapshots_.due(t, tolerance_) || last) {
      auto scope = summary_.phases().measure("output");
      write_snapshot(t, fields);
      if (t > 0.0) snapshots_.passed(t, tolerance_);
    }
  }

  // The controlDict of a start from `start` to `end`: every field written at
  // `end`; MPPICInterFoam's density also one step before (restart_inertia.hpp)
  // and, coupled, its pressure and drag at every step before the end
  // (window_step_means.hpp).
  void write_controls(double start, double end) {
    const long steps = steps_in(end - start);
    ControlSettings settings{.application = c_.solver,
                             .end_time = end,
                             .time_step = c_.time_step,
                             .write_every = steps,
                             .write_density_at = {},
                             .write_steps_between = {}};
    if (c_.has_cloud() && steps > 1) {
      settings.write_density_at = end - c_.time_step;
      if (coupled_) settings.write_steps_between = {start + c_.time_step, end - c_.time_step};
    }
    write_control_dict(case_dir_, settings);
  }

  // MPPICInterFoam's first start: the fluid fraction it starts from (1
  // without soil) as its alphac file, whose product with rho gives the first
  // step its inertia (without the file it reads 0).
  void write_start_fluid_fraction(std::vector<double>& fluid_fraction) {
    if (!c_.has_cloud()) return;
    if (fluid_fraction.empty()) fluid_fraction.assign(mesh_.volumes.size(), 1.0);
    layout_->write_scalar_field(layout_->latest()->name, "alphac", "[0 0 0 0 0 0 0]",
                                fluid_fraction);
  }

  // One start of the solver from its latest time directory (`start`) to
  // `end`, in order: its controls, the solver, the fields it wrote at the end
  // (with MPPICInterFoam, coupled, the means of the window's steps; the next
  // start's inertia), then the time directories no longer needed and the
  // window's costs.
  FoamFields run_window(double start, double end, bool may_repeat = false) {
    const std::string start_name = layout_->latest()->name;
    const long steps = steps_in(end - start);
    WindowTiming timing;
    timing.end_time = end;
    Clock::time_point phase = Clock::now();
    write_controls(start, end);
    timing.write = seconds_since(phase);
    timing.solver = run_solver();
    phase = Clock::now();
    const TimeDirectory written = end_directory(end);
    FoamFields fields = read_fields(written.name);
    if (c_.has_cloud()) {
      if (coupled_ && steps > 1) take_window_step_means(start, steps, fields);
      carry_restart_inertia(start, start_name, end, steps, written.name, fields.alphac);
    }
    timing.read = seconds_since(phase);
    if (!c_.keep_time_directories) {
      // A window that may run again keeps its start directory.
      std::vector<std::string> keep{"0", written.name};
      if (may_repeat) keep.push_back(start_name);
      layout_->remove_times_except(keep);
    }
    steps_ += steps;
    record_costs(timing);
    return fields;
  }

  ApplicationTiming run_solver() {
    return run_application(installation_, c_.solver, {}, case_dir_, log_dir_ / (c_.solver + ".log"),
                           c_.processes,
                           std::chrono::seconds(static_cast<long>(std::ceil(c_.window_timeout))));
  }

  // The directory the solver wrote at the window's end, found by its time
  // (OpenFOAM lengthens a name that two times would share).
  TimeDirectory end_directory(double end) const {
    const auto latest = layout_->latest();
    if (!latest || std::abs(latest->time - end) > tolerance_) {
      throw cosim::Error(
          cosim::ExitCode::participant_failed,
          fmt::format("OpenFOAM's {} ended without writing the time directory of t = {} s ({} "
                      "in {}; its latest is {}; case kept for inspection)",
                      c_.solver, end, time_name(end, time_precision), case_dir_.string(),
                      latest ? latest->name : "none"));
    }
    return *latest;
  }

  // What the soil receives: the means of the window's steps
  // (window_step_means.hpp), whose directories then go.
  void take_window_step_means(double start, long steps, FoamFields& fields) {
    const std::vector<std::string> step_times = window_step_times(start, steps);
    average_over_window_steps(*layout_, step_times, fields, mesh_.mesh.dimension());
    for (std::size_t k = 0; k + 1 < step_times.size(); ++k) layout_->remove_time(step_times[k]);
  }

  // The inertia of MPPICInterFoam's next start (restart_inertia.hpp) from the
  // densities at the window's end `end_name` and one step before it.
  void carry_restart_inertia(double start, const std::string& start_name, double end, long steps,
                             const std::string& end_name,
                             const std::vector<double>& fluid_fraction) {
    const auto before = steps == 1 ? std::optional<TimeDirectory>(TimeDirectory{start, start_name})
                                   : layout_->at(end - c_.time_step, tolerance_);
    if (!before) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("OpenFOAM's {} did not write its density at t = {} s, one "
                                     "step before the window's end (case kept in {})",
                                     c_.solver, end - c_.time_step, case_dir_.string()));
    }
    write_restart_inertia(*layout_, properties_, end_name, before->name, fluid_fraction);
    if (steps > 1) layout_->remove_time(before->name);
  }

  void record_costs(const WindowTiming& timing) {
    summary_.phases().add("adapter_write", timing.write);
    summary_.phases().add("openfoam_startup", timing.solver.startup);
    summary_.phases().add("openfoam_stepping", timing.solver.stepping);
    summary_.phases().add("field_read", timing.read);
    windows_.push_back(timing);
  }

  // The time directories of a window's steps before its end (the last of
  // them also holds the density, restart_inertia.hpp).
  std::vector<std::string> window_step_times(double start, long steps) const {
    std::vector<std::string> names;
    for (long k = 1; k < steps; ++k) {
      const double t = start + static_cast<double>(k) * c_.time_step;
      const auto step = layout_->at(t, tolerance_);
      if (!step) {
        throw cosim::Error(cosim::ExitCode::participant_failed,
                           fmt::format("OpenFOAM's {} did not write its pressure at t = {} s, a "
                                       "step of the window (case kept in {})",
                                       c_.solver, t, case_dir_.string()));
      }
      names.push_back(step->name);
    }
    return names;
  }

  FoamFields read_fields(const std::string& time) const {
    FoamFields f = layout_->read(time, mesh_.mesh.dimension());
    complete_pressure(f, mesh_.centres, properties_);
    return f;
  }

  void write_snapshot(double t, const FoamFields& f) {
    cosim::SnapshotFields fields{{"alpha_water", {f.alpha_water, 1, "1"}},
                                 {"p_rgh", {f.p_rgh, 1, "Pa"}},
                                 {"velocity", {f.velocity, mesh_.mesh.dimension(), "m/s"}}};
    if (!f.p.empty()) fields.emplace("pressure", cosim::FieldView{f.p, 1, "Pa"});
    if (!f.alphac.empty()) fields.emplace("fluid_fraction", cosim::FieldView{f.alphac, 1, "1"});
    snapshot_writer_->write(t, fields);
  }

  // The water's volume sum alpha V and mass; per unit depth in 2D.
  void record_water(const FoamFields& f, bool start) {
    double volume = 0.0;
    for (std::size_t c = 0; c < f.alpha_water.size(); ++c) {
      // MPPICInterFoam's alpha.water is per pore volume.
      const double pores = f.alphac.empty() ? 1.0 : f.alphac[c];
      volume += pores * f.alpha_water[c] * properties_.declared_volume(mesh_.volumes[c]);
    }
    const bool plane = properties_.dimension == 2;
    const auto set = [&](const std::string& name, double value, const std::string& unit) {
      if (start)
        summary_.set_conserved_start(name, value, unit);
      else
        summary_.set_conserved_end(name, value, unit);
    };
    set("volume_water", volume, plane ? "m^2" : "m^3");
    set("mass_water", volume * properties_.water.density, plane ? "kg/m" : "kg");
  }

  const CaseDescription& c_;
  const cosim::SolverCommandLine& options_;
  cosim::RunSummary& summary_;
  fs::path case_dir_;
  fs::path log_dir_;
  cosim::OutputSchedule snapshots_;
  double tolerance_;
  Installation installation_;
  CaseProperties properties_;
  CaseMesh mesh_;
  std::optional<CaseLayout> layout_;
  std::optional<cosim::SnapshotWriter> snapshot_writer_;
  std::vector<WindowTiming> windows_;
  std::int64_t steps_ = 0;
  // Exchanging with a soil: the pressure and drag sent are the window's means
  // (window_step_means.hpp).
  bool coupled_ = false;
  std::optional<GaugeRecorder> gauges_;
  std::optional<SoilExchangeRecord> soil_record_;  // coupled
  std::optional<WindowStart> window_start_;        // implicit coupling
  std::size_t state_restores_ = 0;
  std::size_t parcels_ = 0;                 // or the porosity zones' cells
  std::size_t windows_before_restart_ = 0;  // the windows a checkpoint's run had completed
};

// --overwrite clears the output directory: it must not hold the user's own
// OpenFOAM case (a case that does not load is reported by the run itself).
void check_overwrite_spares_the_case(const cosim::SolverCommandLine& options) {
  if (options.reuse != cosim::OutputReuse::overwrite) return;
  fs::path directory;
  try {
    directory = load_case(options.config).directory;
  } catch (const cosim::Error&) {
    return;
  }
  if (!directory.empty() && cosim::is_inside(directory, options.output))
    throw cosim::InputError(
        fmt::format("--overwrite would clear '{}', which holds the OpenFOAM "
                    "case '{}' of {}",
                    options.output.string(), directory.string(), options.config.string()));
}

}  // namespace

int run_case(const cosim::SolverCommandLine& options) {
  check_overwrite_spares_the_case(options);
  // The run's case/ copy (its processor directories too) goes with the rest
  // of an earlier run on --overwrite.
  cosim::prepare_output_directory(options.output, options.reuse);
  cosim::init_logging(options.output, "openfoam_adapter", options.verbosity);
  cosim::RunSummary summary(options.output, "openfoam_adapter");
  return cosim::run_and_finish(summary, [&] {
    const CaseDescription description = [&] {
      auto scope = summary.phases().measure("read_case");
      return load_case(options.config, options.endpoint.solver_processes);
    }();
    summary.set_config(options.config, description.config_hash);
    spdlog::info("size: {} (limits.memory_gib {:g})", description.size.describe(),
                 description.size.memory_limit_gib);
    summary.set_section("size", description.size.to_json());
    CaseRun run(description, options, summary);
    if (options.endpoint.is_standalone())
      run.run();
    else
      run.run_coupled();
  });
}

}  // namespace openfoam

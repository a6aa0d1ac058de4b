#include "mpm/coupling/coupling_observer.hpp"

#include "cosim/config/document.hpp"

namespace mpm::coupling {

namespace {

template <int Dim>
nlohmann::json vector_json(const Vec<Dim>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int k = 0; k < Dim; ++k) a.push_back(v[k]);
  return a;
}

CouplingSpec coupling_spec_of(const CaseDescription& description) {
  if (description.file.empty()) return {};
  const auto document = cosim::config::Document::load_file(description.file);
  const auto block = document.root().find("coupling");
  if (!block || block->is_null()) return {};
  return read_coupling(*block, description.dimension, description.thermal.enabled);
}

}  // namespace

template <int Dim>
CouplingObserver<Dim>::CouplingObserver(cosim::CouplingEndpoint endpoint, std::string name,
                                        CouplingSpec spec, double standalone_window)
    : endpoint_(std::move(endpoint)),
      name_(std::move(name)),
      spec_(std::move(spec)),
      standalone_window_(standalone_window) {}

template <int Dim>
void CouplingObserver<Dim>::initialize(Solver<Dim>& solver) {
  participant_ = std::make_unique<cosim::Participant>(endpoint_.name_or(name_), endpoint_);
  participant_->declare_repeatable();
  participant_->declare_checkpointable();
  participant_->declare_restartable_on_other_ranks();
  if (standalone_window_ > 0.0) participant_->set_standalone_window(standalone_window_);
  coupling_ = attach_coupling(solver, *participant_, spec_);
  coupling_->declare();
  participant_->initialize(solver.time(), solver.description().time.end_time);
  if (participant_->must_save_state()) coupling_->save_state();
}

template <int Dim>
double CouplingObserver<Dim>::max_time_step() const {
  return participant_->max_time_step();
}

template <int Dim>
void CouplingObserver<Dim>::after_step(Solver<Dim>& /*solver*/, double dt) {
  coupling_->after_step(dt);
  participant_->advance(dt);
  if (participant_->must_restore_state()) coupling_->restore_state();
  if (participant_->is_window_complete()) coupling_->log_held_warnings();
  if (participant_->must_save_state()) coupling_->save_state();
}

template <int Dim>
bool CouplingObserver<Dim>::is_ongoing() const {
  return participant_ && participant_->is_coupling_ongoing();
}

template <int Dim>
bool CouplingObserver<Dim>::must_save_state() const {
  return participant_ && participant_->must_save_state();
}

template <int Dim>
bool CouplingObserver<Dim>::must_restore_state() const {
  return participant_ && participant_->must_restore_state();
}

template <int Dim>
bool CouplingObserver<Dim>::is_window_complete() const {
  return participant_ && participant_->is_window_complete();
}

template <int Dim>
std::filesystem::path CouplingObserver<Dim>::restart_directory() const {
  return participant_ ? participant_->restart_directory() : endpoint_.restart;
}

template <int Dim>
std::vector<std::filesystem::path> CouplingObserver<Dim>::restart_parts() const {
  return participant_ ? participant_->restart_parts() : std::vector<std::filesystem::path>{};
}

template <int Dim>
bool CouplingObserver<Dim>::must_write_checkpoint() const {
  return participant_ && participant_->must_write_checkpoint();
}

template <int Dim>
std::filesystem::path CouplingObserver<Dim>::checkpoint_directory() const {
  return participant_ ? participant_->checkpoint_directory() : std::filesystem::path();
}

template <int Dim>
void CouplingObserver<Dim>::checkpoint_written() {
  participant_->checkpoint_written();
}

template <int Dim>
void CouplingObserver<Dim>::finalize() {
  if (participant_) participant_->finalize();
}

template <int Dim>
void CouplingObserver<Dim>::abort(std::string_view reason) {
  if (participant_) participant_->abort(reason);
}

template <int Dim>
nlohmann::json CouplingObserver<Dim>::summary(GridPartition<Dim>* ranks) const {
  if (!participant_ || !coupling_) return nullptr;
  const auto& t = participant_->timings();
  CouplingDiagnostics<Dim> d = coupling_->diagnostics();
  if (ranks) {
    // Each rank's points took their own shares of the impulse and the heat.
    std::vector<double> applied(d.impulse_total.applied.data(),
                                d.impulse_total.applied.data() + Dim);
    applied.push_back(d.heat_total.applied);
    ranks->sum(applied);
    d.impulse_total.applied = Eigen::Map<const Vec<Dim>>(applied.data());
    d.heat_total.applied = applied.back();
  }
  return {{"participant", participant_->name()},
          {"coupled", participant_->is_coupled()},
          {"windows", t.windows},
          {"iterations", t.iterations},
          {"waiting_s", t.waiting},
          {"transport_s", t.transport},
          {"writes", d.writes},
          {"held_cells", d.held_cells},
          {"capped_solid_fraction_cells", d.capped_solid_fraction_cells},
          {"overfilled_cells", d.overfilled_cells},
          {"impulse_received", vector_json<Dim>(d.impulse_total.received)},
          {"impulse_applied", vector_json<Dim>(d.impulse_total.applied)},
          {"impulse_absorbed", vector_json<Dim>(d.impulse_total.absorbed)},
          {"heat_received", d.heat_total.received},
          {"heat_applied", d.heat_total.applied},
          {"heat_absorbed", d.heat_total.absorbed}};
}

StepObservers coupling_observers(const cosim::CouplingEndpoint& endpoint,
                                 const std::string& default_name) {
  StepObservers observers;
  observers.for_2d = [endpoint,
                      default_name](const CaseDescription& d) -> std::unique_ptr<StepObserver<2>> {
    return std::make_unique<CouplingObserver<2>>(endpoint, default_name, coupling_spec_of(d),
                                                 d.time.window);
  };
  observers.for_3d = [endpoint,
                      default_name](const CaseDescription& d) -> std::unique_ptr<StepObserver<3>> {
    return std::make_unique<CouplingObserver<3>>(endpoint, default_name, coupling_spec_of(d),
                                                 d.time.window);
  };
  return observers;
}

StepObservers standalone_observers(const cosim::CouplingEndpoint& endpoint,
                                   const std::string& default_name) {
  const auto windowed = [endpoint](const CaseDescription& d) {
    return d.time.window > 0.0 || endpoint.repeat_windows;
  };
  StepObservers observers;
  observers.for_2d = [endpoint, default_name,
                      windowed](const CaseDescription& d) -> std::unique_ptr<StepObserver<2>> {
    if (!windowed(d)) return nullptr;
    return std::make_unique<CouplingObserver<2>>(endpoint, default_name, CouplingSpec{},
                                                 d.time.window);
  };
  observers.for_3d = [endpoint, default_name,
                      windowed](const CaseDescription& d) -> std::unique_ptr<StepObserver<3>> {
    if (!windowed(d)) return nullptr;
    return std::make_unique<CouplingObserver<3>>(endpoint, default_name, CouplingSpec{},
                                                 d.time.window);
  };
  return observers;
}

template class CouplingObserver<2>;
template class CouplingObserver<3>;

}  // namespace mpm::coupling

#pragma once

#include <memory>
#include <string>

#include "cosim/participant.hpp"
#include "mpm/coupling/coupling_spec.hpp"
#include "mpm/coupling/mpm_coupling.hpp"
#include "mpm/io/step_observer.hpp"

// The coupled run of mpm_solver: a StepObserver (mpm/io/step_observer.hpp)
// that owns the cosim::Participant and the MpmCoupling and runs the call
// order of mpm_coupling.hpp inside mpm::run_case:
//
//   initialize(solver)    participant (repeatable), attach_coupling, declare,
//                         participant.initialize
//   max_time_step()       participant.max_time_step()
//   after_step(dt)        coupling.after_step(dt), participant.advance(dt), then
//                         the coupling's state restored (the window runs again)
//                         or saved (a window that may run again starts)
//   is_ongoing()          participant.is_coupling_ongoing()
//   finalize() / abort()  participant.finalize() / abort(reason)
//
// Standalone (no endpoint) the participant runs the case in windows of
// `standalone_window` (0: one window), each run twice with
// --cosim-repeat-windows.
namespace mpm::coupling {

template <int Dim>
class CouplingObserver final : public StepObserver<Dim> {
 public:
  CouplingObserver(cosim::CouplingEndpoint endpoint, std::string name, CouplingSpec spec,
                   double standalone_window = 0.0);

  void initialize(Solver<Dim>& solver) override;
  double max_time_step() const override;
  void after_step(Solver<Dim>& solver, double dt) override;
  bool is_ongoing() const override;
  bool must_save_state() const override;
  bool must_restore_state() const override;
  bool is_window_complete() const override;
  void finalize() override;
  void abort(std::string_view reason) override;
  nlohmann::json summary(GridPartition<Dim>* ranks) const override;
  std::filesystem::path restart_directory() const override;
  std::vector<std::filesystem::path> restart_parts() const override;
  bool must_write_checkpoint() const override;
  std::filesystem::path checkpoint_directory() const override;
  void checkpoint_written() override;

  const MpmCoupling<Dim>* coupling() const { return coupling_.get(); }

 private:
  cosim::CouplingEndpoint endpoint_;
  std::string name_;
  CouplingSpec spec_;
  double standalone_window_;
  std::unique_ptr<cosim::Participant> participant_;
  std::unique_ptr<MpmCoupling<Dim>> coupling_;
};

// The observers mpm_solver passes to run_case for a coupled run: each reads
// the `coupling` block of the case file (description.file; absent: nothing
// is declared) and joins the job as endpoint.name_or(default_name).
StepObservers coupling_observers(const cosim::CouplingEndpoint& endpoint,
                                 const std::string& default_name = "mpm");

// The observers of a standalone run (an endpoint without uri): none, unless
// the case gives time.window or the command line --cosim-repeat-windows;
// then a standalone participant runs the case in those windows (the
// `coupling` block is ignored standalone: nothing is declared or read).
StepObservers standalone_observers(const cosim::CouplingEndpoint& endpoint,
                                   const std::string& default_name = "mpm");

extern template class CouplingObserver<2>;
extern template class CouplingObserver<3>;

}  // namespace mpm::coupling

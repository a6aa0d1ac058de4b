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
//   initialize(solver)    participant, attach_coupling, declare, participant.initialize
//   max_time_step()       participant.max_time_step()
//   after_step(dt)        coupling.after_step(dt), participant.advance(dt)
//   is_ongoing()          participant.is_coupling_ongoing()
//   finalize() / abort()  participant.finalize() / abort(reason)
namespace mpm::coupling {

template <int Dim>
class CouplingObserver final : public StepObserver<Dim> {
 public:
  CouplingObserver(cosim::CouplingEndpoint endpoint, std::string name, CouplingSpec spec);

  void initialize(Solver<Dim>& solver) override;
  double max_time_step() const override;
  void after_step(Solver<Dim>& solver, double dt) override;
  bool is_ongoing() const override;
  void finalize() override;
  void abort(std::string_view reason) override;
  nlohmann::json summary() const override;

  const MpmCoupling<Dim>* coupling() const { return coupling_.get(); }

 private:
  cosim::CouplingEndpoint endpoint_;
  std::string name_;
  CouplingSpec spec_;
  std::unique_ptr<cosim::Participant> participant_;
  std::unique_ptr<MpmCoupling<Dim>> coupling_;
};

// The observers mpm_solver passes to run_case for a coupled run: each reads
// the `coupling` block of the case file (description.file; absent: nothing
// is declared) and joins the job as endpoint.name_or(default_name).
StepObservers coupling_observers(const cosim::CouplingEndpoint& endpoint,
                                 const std::string& default_name = "mpm");

extern template class CouplingObserver<2>;
extern template class CouplingObserver<3>;

}  // namespace mpm::coupling

#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "mpm/solver/solver.hpp"

namespace mpm {

// Something that runs alongside the time loop of run_case: the coupling
// with a fluid (a cosim::Participant) plugs in here. The driver calls
//
//   initialize(solver)                  once, after the solver is built and
//                                       before the first output; register
//                                       force sources / grid corrections on
//                                       the solver here, declare meshes and
//                                       fields, connect
//   while (is_ongoing()):               (standalone: while t < end_time)
//     if must_save_state():             save the solver's state and the driver's
//     dt = min(stable step, max_time_step(), time to the next output)
//     solver.step(dt)
//     after_step(solver, dt)            write fields, advance the window
//     if must_restore_state():          restore both, run the window again
//   finalize() | abort(reason)          at the end, or on any error
//
// While an observer is present its is_ongoing() alone decides when the run
// ends (a coupled run's end time is the job's); outputs still follow the
// case's output.every and time.end_time.
//
// Implicit coupling repeats a window until the exchanged fields converge
// (architecture.md §13). An observer that may repeat windows says so with
// must_save_state() at each window's start and must_restore_state() after
// the after_step() that ended a window which must run again; it saves and
// restores its own state itself (in after_step). Outputs that fall due
// inside a window that may run again are held until is_window_complete(),
// and dropped on a restore: a repeated window leaves no trace.
template <int Dim>
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void initialize(Solver<Dim>& solver) = 0;
  virtual double max_time_step() const { return std::numeric_limits<double>::infinity(); }
  virtual void after_step(Solver<Dim>& solver, double dt) = 0;
  virtual bool is_ongoing() const = 0;
  virtual bool must_save_state() const { return false; }
  virtual bool must_restore_state() const { return false; }
  virtual bool is_window_complete() const { return true; }
  virtual void finalize() {}
  virtual void abort(std::string_view reason) { (void)reason; }
  // Added to summary.json under "coupling" (timings, windows), when not null.
  // `ranks`: on a rank of a decomposed run whose ranks all end together,
  // the partition that sums what each rank's points took over the ranks
  // (collective); nullptr otherwise.
  virtual nlohmann::json summary(GridPartition<Dim>* ranks) const {
    (void)ranks;
    return nullptr;
  }

  // Checkpoints of a coupled run (architecture.md §14): the driver reads the
  // solver's and its own state from restart_directory() after initialize()
  // when it is not empty, and after the after_step() that completed a window
  // with must_write_checkpoint() writes them into checkpoint_directory(),
  // then calls checkpoint_written().
  virtual std::filesystem::path restart_directory() const { return {}; }
  // After initialize(), on a restart: the directories the checkpoint's ranks
  // wrote, in rank order (one for a checkpoint of one process).
  virtual std::vector<std::filesystem::path> restart_parts() const { return {}; }
  virtual bool must_write_checkpoint() const { return false; }
  virtual std::filesystem::path checkpoint_directory() const { return {}; }
  virtual void checkpoint_written() {}
};

template <int Dim>
using StepObserverFactory =
    std::function<std::unique_ptr<StepObserver<Dim>>(const CaseDescription& description)>;

// One factory per dimension (either may be empty: no observer).
struct StepObservers {
  StepObserverFactory<2> for_2d;
  StepObserverFactory<3> for_3d;
};

}  // namespace mpm

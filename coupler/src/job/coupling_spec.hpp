#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "com/handshake.hpp"
#include "cosim/error.hpp"

namespace cosim::config {
class Node;
}

// The coupling scheme of a job (`coupling:`): how the participants' windows
// are ordered and whether a window is repeated until the exchanged fields
// converge (architecture.md §13).
namespace cosim::job {

struct Job;

enum class Scheme {
  // Every participant runs a window at once on the fields of the window
  // before (the default; one exchange per window).
  parallel_explicit,
  // As parallel-explicit, but the window is repeated from its start, with
  // every participant restoring its saved state, until the fields the
  // coupler sends stop changing (preCICE's parallel-implicit scheme).
  parallel_implicit,
  // Two participants, one after the other: `first` runs a window on the
  // second's values of the window before, then the second runs it on the
  // first's new values (a Gauss-Seidel step across the interface).
  serial_explicit,
  // As serial-explicit, repeated until converged; the accelerated fields are
  // those sent to `first` (preCICE's serial-implicit scheme).
  serial_implicit,
};

// A field the coupler sends a participant, as `<participant>.<field>`.
struct SentField {
  std::string participant;
  std::string field;
  std::string label() const { return participant + "." + field; }
};

// One convergence measure (preCICE's, with r = H(x) - x the change of the
// field over an iteration, in the discrete 2-norm): the field has converged
// when any limit given holds,
//   relative            ||r^k|| <= relative ||H(x^k)||
//   absolute            ||r^k|| <= absolute
//   residual_relative   ||r^k|| <= residual_relative ||r^1||  (iterations >= 2)
struct ConvergenceMeasure {
  SentField field;
  std::optional<double> relative;
  std::optional<double> absolute;
  std::optional<double> residual_relative;
  SourceLocation where;
  std::string key_path;
};

enum class OnMaxIterations { continue_run, stop };

struct CouplingSpec {
  Scheme scheme = Scheme::parallel_explicit;
  com::TimeInterpolation time_interpolation = com::TimeInterpolation::constant;
  std::size_t max_iterations = 0;
  OnMaxIterations on_max_iterations = OnMaxIterations::stop;
  // A residual norm that grows by more than this factor over one iteration,
  // to more than a tenth of the field's norm, stops the run (exit 4).
  double divergence_factor = 0.0;
  std::vector<ConvergenceMeasure> convergence;
  acceleration::AccelerationSpec acceleration;
  // The fields the accelerator updates, in this order; the others take
  // H(x) as it is. Default: every field the coupler sends (serial schemes:
  // sends `first`) but an exchange's answers.
  std::vector<SentField> accelerated;
  // Serial schemes: the participant that runs each window first, and the other.
  std::string first;
  std::string second;
  SourceLocation where;  // of `coupling`, or of the job when absent
  SourceLocation scheme_where;

  bool is_implicit() const {
    return scheme == Scheme::parallel_implicit || scheme == Scheme::serial_implicit;
  }
  bool is_serial() const {
    return scheme == Scheme::serial_explicit || scheme == Scheme::serial_implicit;
  }
};

// The keys of `coupling:` the file gives (before the schema's defaults are
// added): `scheme`, ..., and `acceleration.<key>`.
std::set<std::string> written_coupling_keys(const config::Node& root);

// `coupling:` with its defaults, read and checked against the job's
// participants and the fields the coupler sends them (load_job calls it once
// the exchanges are known); `written` says which keys the file gave.
CouplingSpec read_coupling(const Job& job, const config::Node& coupling,
                           const std::set<std::string>& written);

}  // namespace cosim::job

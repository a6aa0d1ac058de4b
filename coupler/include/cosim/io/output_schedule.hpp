#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cosim/config/node.hpp"
#include "cosim/error.hpp"

namespace cosim {

// The most outputs (snapshots, gauge or probe rows) one schedule may hold
// over a run. More is a mistake, usually in an exponent, that would fill
// the disk or never end; it also keeps every interval far above the end
// time's round-off (end_time * 2^-52), where k * interval stops telling
// outputs apart.
inline constexpr double max_output_count = 1e6;

// How many outputs `interval` gives after the start up to end_time (0: the
// end only), as a real number: a multiple of the interval lands on the end
// time to round-off.
inline double output_count(double interval, double end_time) {
  return interval > 0.0 ? std::max(1.0, end_time / interval) : 1.0;
}

// Why `interval` cannot be a run's output interval, or "" when it can.
inline std::string output_interval_problem(double interval, double end_time) {
  const double count = output_count(interval, end_time);
  if (count <= max_output_count * (1.0 + 1e-9)) return {};
  return fmt::format(
      "an interval of {:g} s gives {:.3g} outputs over the run's {:g} s, more than {:g}; give a "
      "longer interval (or 0: the end only)",
      interval, count, end_time, max_output_count);
}

// Refuses, located at the key, an output interval read from `interval`
// that gives more than max_output_count outputs up to `end_time`.
inline void check_output_interval(const config::Node& interval, double end_time) {
  const std::string problem = output_interval_problem(interval.as<double>(), end_time);
  if (!problem.empty()) interval.fail(problem);
}

// When a solver writes an output: at k * interval (k = 1, 2, ...) and at the
// end time; interval 0 means the end time only. Times are computed, not
// accumulated, so a step that ends on one lands on it to round-off. Solvers
// shorten their step to next() - t so that outputs fall on these times.
class OutputSchedule {
 public:
  // Throws InputError when the interval gives more than max_output_count
  // outputs (the case files check this where they are read; a coupled run's
  // end time, the job's, is only known here).
  OutputSchedule(double interval, double end_time) : interval_(interval), end_(end_time) {
    const std::string problem = output_interval_problem(interval, end_time);
    if (!problem.empty()) throw InputError("output: " + problem);
  }

  double next() const {
    if (done_) return std::numeric_limits<double>::infinity();
    return interval_ > 0.0 ? std::min(k_ * interval_, end_) : end_;
  }
  bool due(double t, double tolerance) const { return next() <= t + tolerance; }
  // Moves past every output time up to t: to the first k with k * interval
  // beyond t + tolerance, found by division (never one interval at a time),
  // then corrected by one for the division's round-off either way.
  void passed(double t, double tolerance) {
    if (end_ <= t + tolerance) done_ = true;
    if (!(interval_ > 0.0)) return;
    const double reached = t + tolerance;
    double k = std::floor(reached / interval_) + 1.0;
    if (k * interval_ <= reached) k += 1.0;
    if ((k - 1.0) * interval_ > reached && k - 1.0 >= 1.0) k -= 1.0;
    k_ = std::max(k_, k);
  }

  // Where the schedule stands, for a checkpoint: the next multiple k of the
  // interval and whether the end is passed; resume() puts it back.
  struct Position {
    double k = 1.0;
    bool done = false;
  };
  Position position() const { return {k_, done_}; }
  void resume(Position p) {
    k_ = p.k;
    done_ = p.done;
  }

 private:
  double interval_;
  double end_;
  double k_ = 1.0;  // a double: exact up to 2^53, far beyond max_output_count
  bool done_ = false;
};

}  // namespace cosim

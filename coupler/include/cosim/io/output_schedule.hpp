#pragma once

#include <algorithm>
#include <limits>

namespace cosim {

// When a solver writes an output: at k * interval (k = 1, 2, ...) and at the
// end time; interval 0 means the end time only. Times are computed, not
// accumulated, so a step that ends on one lands on it to round-off. Solvers
// shorten their step to next() - t so that outputs fall on these times.
class OutputSchedule {
 public:
  OutputSchedule(double interval, double end_time) : interval_(interval), end_(end_time) {}

  double next() const {
    if (done_) return std::numeric_limits<double>::infinity();
    return interval_ > 0.0 ? std::min(static_cast<double>(k_) * interval_, end_) : end_;
  }
  bool due(double t, double tolerance) const { return next() <= t + tolerance; }
  // Moves past every output time up to t.
  void passed(double t, double tolerance) {
    if (end_ <= t + tolerance) done_ = true;
    while (interval_ > 0.0 && static_cast<double>(k_) * interval_ <= t + tolerance) ++k_;
  }

 private:
  double interval_;
  double end_;
  long k_ = 1;
  bool done_ = false;
};

}  // namespace cosim

#pragma once

#include <chrono>
#include <cstddef>

namespace cosim::cplscheme {

// One progress line per window on a terminal (rewritten in place), or a
// plain log line about every ten seconds otherwise.
class Progress {
 public:
  Progress(double start_time, double end_time, std::size_t windows, bool terminal);
  // `iterations`: an implicit window's iterations (0: explicit, not shown).
  void update(std::size_t window, double time, std::size_t iterations = 0);
  void finish();

 private:
  double start_time_;
  double end_time_;
  std::size_t windows_;
  bool terminal_;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point last_report_;
};

}  // namespace cosim::cplscheme

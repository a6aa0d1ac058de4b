#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/run_layout.hpp"
#include "bench/suite.hpp"

namespace cosim::bench {

// What a quantity gave: a number, or a curve (a profile against position or
// a time series against time). A profile remembers the time of its snapshot,
// at which an analytic reference is evaluated.
struct Measurement {
  std::optional<double> value;
  std::vector<double> x, y;
  double time = 0.0;
  std::string abscissa;  // "x [m]", "t [s]", ...
  bool is_curve() const { return !x.empty(); }
};

// Reads one quantity from a finished run (the kinds of the suite schema:
// gauge, time_series, profile, water_front, soil, summary). Throws Error
// saying what is missing (a file, a column, a field) when the run did not
// record it.
Measurement measure(const QuantitySpec& quantity, const RunLayout& run);

}  // namespace cosim::bench

#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/quantity.hpp"
#include "bench/suite.hpp"

namespace cosim::bench {

enum class Verdict {
  pass,         // within tolerance
  fail,         // outside it
  measured,     // no tolerance: reported only
  unavailable,  // the run failed, or did not record the quantity
};
std::string to_string(Verdict v);

// One metric of one run: its value, the reference's, the error between
// them and the verdict; for curves also the two curves (for the plots).
struct MetricResult {
  std::optional<double> value;
  std::optional<double> reference;
  std::string reference_label;
  std::optional<double> error;
  std::optional<double> tolerance;
  Verdict verdict = Verdict::unavailable;
  std::string note;  // why unavailable, or how the error was found (e.g. the fitted offset)
  Measurement measured;
  std::vector<double> reference_x, reference_y;  // a reference curve, where there is one
};

// Compares a measurement with the metric's reference. Reference files are
// read here; their problems (a missing column, no matching row) make the
// result unavailable with a note rather than stopping the suite.
MetricResult evaluate(const MetricSpec& metric, const std::string& backend,
                      const Measurement& measured);

// A result for a run that failed or could not be measured.
MetricResult unavailable(const MetricSpec& metric, const std::string& backend,
                         const std::string& why);

// The curve y(x) interpolated linearly at `at`, held constant beyond its ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at);

}  // namespace cosim::bench

#pragma once

#include <filesystem>
#include <vector>

#include "cosim/io/held_outputs.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "swe/case/case_description.hpp"
#include "swe/solver.hpp"

namespace swe {

// gauges.csv: time, then per gauge the free surface eta, the depth and the
// speed of the cell holding the gauge (the cell average the finite volumes
// carry).
class GaugeRecorder {
 public:
  GaugeRecorder(const std::filesystem::path& file, const std::vector<Gauge>& gauges,
                const Solver& solver);
  // Appends the row of `time` through `outputs` (held while its window may
  // run again).
  void record(double time, const Solver& solver, cosim::HeldOutputs& outputs);
  std::size_t rows() const { return writer_.rows_written(); }

 private:
  std::vector<std::size_t> cells_;
  cosim::TimeSeriesWriter writer_;
  std::vector<double> row_;
};

}  // namespace swe

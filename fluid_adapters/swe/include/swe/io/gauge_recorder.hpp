#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "cosim/io/held_outputs.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "swe/case/case_description.hpp"
#include "swe/io/run_ranks.hpp"
#include "swe/solver.hpp"

namespace swe {

// gauges.csv: time, then per gauge the free surface eta, the depth and the
// speed of the cell holding the gauge (the cell average the finite volumes
// carry). Decomposed over ranks, each rank samples the gauges its block
// holds (zeros for the others), rank 0 writes the rows summed over the ranks.
class GaugeRecorder {
 public:
  // `file` is written only where ranks.writes_outputs().
  GaugeRecorder(const std::filesystem::path& file, const std::vector<Gauge>& gauges,
                const Solver& solver, const RunRanks& ranks);
  // Appends the row of `time` through `outputs` (held while its window may
  // run again). Collective when decomposed.
  void record(double time, const Solver& solver, cosim::HeldOutputs& outputs);
  std::size_t rows() const { return writer_ ? writer_->rows_written() : 0; }

 private:
  const RunRanks& ranks_;
  std::vector<std::size_t> cells_;
  std::optional<cosim::TimeSeriesWriter> writer_;
  std::vector<double> row_;
};

}  // namespace swe

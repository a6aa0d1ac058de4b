#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>

#include "cosim/io/run_summary.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "openfoam/io/soil_coupling.hpp"

namespace openfoam {

// The record of the exchange with the soil: soil_exchange.csv, a row per
// window of the cloud's momentum on the water against the drag law's, the
// worst over the run for the summary, and a warning whenever the window
// limits the drag in more cells than ever before.
class SoilExchangeRecord {
 public:
  explicit SoilExchangeRecord(const std::filesystem::path& file);

  // The window of length `window` ending at `t`, with `parcels` soil parcels
  // (or cells of the porosity zones).
  void record(const SoilCoupling::MomentumCheck& check, double window, double t,
              std::size_t parcels);
  void set_metrics(cosim::RunSummary& summary) const;
  double worst_mismatch() const { return worst_mismatch_; }

 private:
  void warn_of_limited_drag(const SoilCoupling::MomentumCheck& check, double window, double t);

  cosim::TimeSeriesWriter csv_;
  double worst_mismatch_ = 0.0;
  std::size_t most_limited_cells_ = 0;
  std::size_t warned_limited_cells_ = 0;
  double shortest_relaxation_ = INFINITY;
};

}  // namespace openfoam

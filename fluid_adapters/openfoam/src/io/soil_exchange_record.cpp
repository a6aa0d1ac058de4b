#include "openfoam/io/soil_exchange_record.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <string>
#include <vector>

namespace openfoam {

SoilExchangeRecord::SoilExchangeRecord(const std::filesystem::path& file)
    : csv_(file, std::vector<std::string>{"time_s", "parcels", "cloud_on_fluid_kg_m/s",
                                          "law_on_fluid_kg_m/s", "to_soil_kg_m/s", "mismatch_1",
                                          "drag_limited_cells"}) {}

void SoilExchangeRecord::record(const SoilCoupling::MomentumCheck& check, double window, double t,
                                std::size_t parcels) {
  worst_mismatch_ = std::max(worst_mismatch_, check.mismatch);
  warn_of_limited_drag(check, window, t);
  csv_.append({t, static_cast<double>(parcels), check.cloud_on_fluid, check.law_on_fluid,
               check.to_soil, check.mismatch, static_cast<double>(check.limited_cells)});
}

// The explicit exchange gives the soil at most what brings it to the
// water's velocity in a window: where the window outlasts the soil's
// relaxation time the drag is cut, and the user is told once, and again
// whenever more cells are cut than ever before.
void SoilExchangeRecord::warn_of_limited_drag(const SoilCoupling::MomentumCheck& check,
                                              double window, double t) {
  most_limited_cells_ = std::max(most_limited_cells_, check.limited_cells);
  shortest_relaxation_ = std::min(shortest_relaxation_, check.shortest_relaxation);
  if (check.limited_cells <= warned_limited_cells_) return;
  warned_limited_cells_ = check.limited_cells;
  spdlog::warn(
      "t = {:.6g} s: the window {:g} s outlasts the soil's drag relaxation time (down to {:.3g} "
      "s) in {} cell(s): their drag is limited to what brings the soil to the water's velocity "
      "(beta T = 1); a window of {:.2g} s or less resolves it",
      t, window, check.shortest_relaxation, check.limited_cells, check.shortest_relaxation);
}

void SoilExchangeRecord::set_metrics(cosim::RunSummary& summary) const {
  summary.set_metric("cloud_momentum_mismatch_max", worst_mismatch_, "1");
  summary.set_metric("drag_limited_cells_max", static_cast<double>(most_limited_cells_), "1");
  if (most_limited_cells_ > 0)
    summary.set_metric("drag_relaxation_time_min", shortest_relaxation_, "s");
}

}  // namespace openfoam

#include "swe/io/gauge_recorder.hpp"

#include <cmath>

namespace swe {

namespace {

std::vector<std::string> gauge_columns(const std::vector<Gauge>& gauges) {
  std::vector<std::string> columns{cosim::column_name("time", "s")};
  for (const Gauge& g : gauges) {
    columns.push_back(cosim::column_name("eta_" + g.name, "m"));
    columns.push_back(cosim::column_name("h_" + g.name, "m"));
    columns.push_back(cosim::column_name("speed_" + g.name, "m/s"));
  }
  return columns;
}

}  // namespace

GaugeRecorder::GaugeRecorder(const std::filesystem::path& file, const std::vector<Gauge>& gauges,
                             const Solver& solver, const RunRanks& ranks)
    : ranks_(ranks) {
  if (ranks.writes_outputs()) writer_.emplace(file, gauge_columns(gauges));
  for (const Gauge& g : gauges) cells_.push_back(ranks.cell_at(solver, g.x, g.y));
  row_.resize(1 + 3 * cells_.size());
}

void GaugeRecorder::record(double time, const Solver& solver, cosim::HeldOutputs& outputs) {
  const auto h = solver.depth();
  const auto bed = solver.bed();
  const auto qx = solver.discharge_x();
  const auto qy = solver.discharge_y();
  const double dry = solver.physics().dry_depth;
  row_[0] = time;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const std::size_t c = cells_[k];
    if (c >= h.size()) {  // another rank's
      row_[1 + 3 * k] = row_[2 + 3 * k] = row_[3 + 3 * k] = 0.0;
      continue;
    }
    const double q = qy.empty() ? std::abs(qx[c]) : std::hypot(qx[c], qy[c]);
    row_[1 + 3 * k] = h[c] + bed[c];
    row_[2 + 3 * k] = h[c];
    row_[3 + 3 * k] = h[c] > dry ? q / h[c] : 0.0;
  }
  ranks_.sum(std::span<double>(row_).subspan(1));
  if (writer_) outputs.append(*writer_, row_);
}

}  // namespace swe

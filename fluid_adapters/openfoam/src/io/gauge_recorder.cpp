#include "openfoam/io/gauge_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace openfoam {

namespace {

std::size_t nearest_cell(const CaseMesh& mesh, const Gauge& gauge) {
  const int dim = mesh.mesh.dimension();
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < mesh.volumes.size(); ++c) {
    double d2 = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(dim); ++k) {
      const double dx = mesh.centres[3 * c + k] - gauge.point[k];
      d2 += dx * dx;
    }
    if (d2 < best_distance) {
      best_distance = d2;
      best = c;
    }
  }
  return best;
}

// The cells of the generated grid's column at (x, z), bottom to top (x fastest).
std::vector<std::size_t> column_cells(const GeneratedCase& box, const WaveGauge& gauge) {
  const Vector3 h = box.spacing();
  const auto index = [](double x, double origin, double dx, int n) {
    return std::clamp(static_cast<int>(std::floor((x - origin) / dx)), 0, n - 1);
  };
  const int i = index(gauge.x, box.origin[0], h[0], box.cells[0]);
  const int k = box.dimension == 3 ? index(gauge.z, box.origin[2], h[2], box.cells[2]) : 0;
  std::vector<std::size_t> cells;
  for (int j = 0; j < box.cells[1]; ++j)
    cells.push_back(static_cast<std::size_t>(i + box.cells[0] * (j + box.cells[1] * k)));
  return cells;
}

std::vector<std::string> columns(const CaseDescription& c, int dim) {
  std::vector<std::string> names{cosim::column_name("time", "s")};
  for (const Gauge& g : c.gauges) {
    names.push_back(cosim::column_name("p_" + g.name, "Pa"));
    names.push_back(cosim::column_name("p_rgh_" + g.name, "Pa"));
    for (int k = 0; k < dim; ++k)
      names.push_back(cosim::column_name(std::string("u") + "xyz"[k] + "_" + g.name, "m/s"));
    names.push_back(cosim::column_name("water_fraction_" + g.name, "1"));
  }
  for (const WaveGauge& g : c.wave_gauges)
    names.push_back(cosim::column_name("eta_" + g.name, "m"));
  return names;
}

}  // namespace

GaugeRecorder::GaugeRecorder(const CaseDescription& description, const CaseMesh& mesh,
                             const std::filesystem::path& file)
    : dim_(mesh.mesh.dimension()), csv_(file, columns(description, mesh.mesh.dimension())) {
  for (const Gauge& g : description.gauges) gauge_cells_.push_back(nearest_cell(mesh, g));
  if (description.wave_gauges.empty()) return;
  const GeneratedCase& box = *description.generate;
  for (const WaveGauge& g : description.wave_gauges) wave_columns_.push_back(column_cells(box, g));
  floor_ = box.origin[1];
  cell_height_ = box.spacing()[1];
}

void GaugeRecorder::record(double t, const FoamFields& f) {
  const auto dim = static_cast<std::size_t>(dim_);
  std::vector<double> row{t};
  for (std::size_t c : gauge_cells_) {
    row.push_back(f.p[c]);
    row.push_back(f.p_rgh[c]);
    for (std::size_t k = 0; k < dim; ++k) row.push_back(f.velocity[c * dim + k]);
    row.push_back((f.alphac.empty() ? 1.0 : f.alphac[c]) * f.alpha_water[c]);
  }
  for (const auto& column : wave_columns_) {
    // Water and the pores' water alike: a saturated soil's cells count whole.
    double height = floor_;
    for (std::size_t c : column) height += f.alpha_water[c] * cell_height_;
    row.push_back(height);
  }
  csv_.append(row);
}

}  // namespace openfoam

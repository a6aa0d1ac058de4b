#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "cosim/io/time_series_writer.hpp"
#include "openfoam/case/case_description.hpp"
#include "openfoam/io/case_mesh.hpp"
#include "openfoam/io/foam_fields.hpp"

namespace openfoam {

// gauges.csv, a row per window: at each gauge the pressures, velocity and
// water fraction of the cell whose centre is nearest, and at each wave gauge
// of a generated case the water surface's height over its column.
class GaugeRecorder {
 public:
  GaugeRecorder(const CaseDescription& description, const CaseMesh& mesh,
                const std::filesystem::path& file);

  void record(double t, const FoamFields& fields);

 private:
  int dim_ = 0;
  std::vector<std::size_t> gauge_cells_;
  // The cells of each wave gauge's column, bottom to top, and the floor's
  // height and the cells' height of the generated grid.
  std::vector<std::vector<std::size_t>> wave_columns_;
  double floor_ = 0.0;
  double cell_height_ = 0.0;
  cosim::TimeSeriesWriter csv_;
};

}  // namespace openfoam

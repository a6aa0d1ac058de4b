#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "cosim/mesh.hpp"
#include "ice/solver/ice_solver.hpp"

namespace ice {

// The grid as the cell-centred uniform mesh the coupler and the snapshot
// writer know.
template <int Dim>
cosim::Mesh cell_mesh(const CellGrid<Dim>& grid, const std::string& name);

// Snapshot fields of an ICE state (architecture.md §6), cell-centred:
//   pressure [Pa], density (mixture, sum rhobar) [kg/m3], velocity (mixture,
//   mass-weighted) [m/s], and per material <name>: volume_fraction_<name>,
//   bulk_density_<name>, density_<name>, velocity_<name>, temperature_<name>.
template <int Dim>
class SnapshotFieldSet {
 public:
  const cosim::SnapshotFields& fields(const IceSolver<Dim>& solver);

 private:
  std::vector<double> mixture_density_;
  std::vector<double> mixture_velocity_;
  std::vector<std::vector<double>> velocity_;
  cosim::SnapshotFields fields_;
};

struct GaugePoint {
  std::string name;
  std::array<double, 3> point{};
};

// gauges.csv: `time [s]`, then per gauge the pressure, the mixture velocity
// components and each material's volume fraction in the cell holding the
// point, as `<quantity>_<gauge> [unit]` (p, ux, uy, uz, <material>_fraction),
// the columns every backend writes. Throws cosim::InputError for a point
// outside the grid.
template <int Dim>
class GaugeRecorder {
 public:
  GaugeRecorder(const std::filesystem::path& file, const std::vector<GaugePoint>& gauges,
                const IceSolver<Dim>& solver);
  void record(double time, const IceSolver<Dim>& solver);
  // The row record() appends, for a caller that writes it later
  // (HeldOutputs); valid until the next call.
  std::span<const double> row(double time, const IceSolver<Dim>& solver);
  cosim::TimeSeriesWriter& writer() { return writer_; }
  std::size_t rows() const { return writer_.rows_written(); }

 private:
  std::vector<int> cells_;
  cosim::TimeSeriesWriter writer_;
  std::vector<double> row_;
};

}  // namespace ice

#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
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

// A wave gauge: the height of a material's free surface over the column of
// cells through `point` along the vertical axis (the one gravity lies
// along): bottom + sum over the column of phi_m / n dx_v, n the porosity,
// so that a saturated soil's cells count whole as in the other backends.
struct WaveGauge {
  std::string name;
  std::array<double, 3> point{};  // its coordinate along the vertical is ignored
  std::string material = "water";
  int vertical = 1;  // the axis gravity lies along
};

// gauges.csv: `time [s]`, then per gauge the pressure, the mixture velocity
// components and each material's volume fraction in the cell holding the
// point, as `<quantity>_<gauge> [unit]` (p, ux, uy, uz, <material>_fraction),
// then per wave gauge `eta_<gauge> [m]`: the columns every backend writes.
// Throws cosim::InputError for a point outside the grid or a wave gauge's
// unknown material.
//
// Decomposed over MPI ranks (issue 27), each rank computes the values of the
// cells it holds and -0.0 for the others; `sum` adds them over the ranks,
// exactly (x + -0.0 is x), before a wave gauge's column is summed bottom to
// top: every rank count writes the rows of one process.
template <int Dim>
class GaugeRecorder {
 public:
  // Where the gauges lie in a decomposed run: the whole grid, and the cell
  // of the solver's grid holding a cell of the whole grid, or -1 where
  // another rank holds it.
  struct Decomposed {
    CellGrid<Dim> whole;
    std::function<int(int)> local;
  };
  using Sum = std::function<void(std::span<double>)>;

  GaugeRecorder(const std::filesystem::path& file, const std::vector<GaugePoint>& gauges,
                const IceSolver<Dim>& solver, const std::vector<WaveGauge>& wave_gauges = {});
  // A decomposed run's: with `writes` false (ranks other than 0) no file is
  // written, but row() takes part in the sums.
  GaugeRecorder(const std::filesystem::path& file, const std::vector<GaugePoint>& gauges,
                const IceSolver<Dim>& solver, const std::vector<WaveGauge>& wave_gauges,
                const Decomposed& decomposed, bool writes);
  void record(double time, const IceSolver<Dim>& solver);
  // The row record() appends, for a caller that writes it later
  // (HeldOutputs); valid until the next call. Decomposed, `sum` adds values
  // over the ranks in place (collective).
  std::span<const double> row(double time, const IceSolver<Dim>& solver, const Sum& sum = {});
  bool writes() const { return writer_.has_value(); }
  cosim::TimeSeriesWriter& writer() { return *writer_; }
  std::size_t rows() const { return writer_ ? writer_->rows_written() : 0; }

 private:
  struct Column {
    std::vector<int> cells;  // bottom to top; -1: another rank's
    std::size_t material = 0;
    double bottom = 0.0;
    double cell_height = 0.0;
  };
  void locate(const std::vector<GaugePoint>& gauges, const IceSolver<Dim>& solver,
              const std::vector<WaveGauge>& wave_gauges, const CellGrid<Dim>& grid,
              const std::function<int(int)>& local);

  std::vector<int> cells_;  // -1: another rank's
  std::vector<Column> columns_;
  std::optional<cosim::TimeSeriesWriter> writer_;
  std::vector<double> values_;  // the cells' values, then the columns' cells' heights
  std::vector<double> row_;
};

}  // namespace ice

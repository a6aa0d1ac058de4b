#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "cosim/io/time_series_writer.hpp"
#include "mpm/solver/solver.hpp"

namespace mpm {

// `probes.csv`: one row per record, `time [s]` then per probe (the particle
// the loader chose for it) `<probe>_displacement_x [m]` ..,
// `<probe>_velocity_x [m/s]` .., total stress `<probe>_stress_xx [Pa]`
// (xx yy zz xy, and yz xz in 3D; tension positive), `<probe>_pore_pressure [Pa]`
// and `<probe>_plastic_strain [-]`, and `<probe>_temperature [K]` when the
// case conducts heat.
//
// On the ranks of a decomposed run (issue 27) every rank holds the rows
// together: the rank holding a probe's point gives its values, the others
// -0.0, and `sum_over_ranks` adds them (exactly: x + -0.0 is x); only the
// rank that `writes` keeps the file.
template <int Dim>
class ProbeRecorder {
 public:
  using SumOverRanks = std::function<void(std::span<double>)>;
  ProbeRecorder(const std::filesystem::path& file, const Solver<Dim>& solver,
                SumOverRanks sum_over_ranks = {}, bool writes = true);
  void record(const Solver<Dim>& solver);
  std::size_t rows_written() const { return writer_ ? writer_->rows_written() : 0; }

  // A row taken now and kept in memory until write_held() appends it, or
  // drop_held() forgets it (the outputs of a coupling window that may run
  // again). Rows are appended in the order they were held.
  void hold(const Solver<Dim>& solver);
  void write_held();
  void drop_held() { held_.clear(); }
  std::size_t held() const { return held_.size() / columns_; }

  static std::vector<std::string> columns(const std::vector<ProbeSpec>& probes,
                                          bool thermal = false);

 private:
  std::vector<ProbeSpec> probes_;
  bool thermal_;
  SumOverRanks sum_over_ranks_;
  std::vector<Vec<Dim>> initial_position_;  // per probe
  std::optional<cosim::TimeSeriesWriter> writer_;
  std::size_t columns_;
  std::vector<double> held_;  // held rows, one after the other
};

extern template class ProbeRecorder<2>;
extern template class ProbeRecorder<3>;

}  // namespace mpm

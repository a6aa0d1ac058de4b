#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/time_series_writer.hpp"

namespace ice {

// The outputs of a coupling window that may run again (implicit coupling,
// --cosim-repeat-windows): held in memory while the window runs, written in
// order once it completes, dropped when it must run again, so that a
// repeated window leaves no trace. Outside such a window they are written
// straight through. The held copies' storage is kept from window to window.
class HeldOutputs {
 public:
  // At the start of a window that may run again.
  void hold() { holding_ = true; }
  // The window completed: what it held is written; later outputs go
  // straight through until the next hold().
  void release();
  // The window runs again: what it held is forgotten; it still holds.
  void discard();
  bool holding() const { return holding_; }

  void append(cosim::TimeSeriesWriter& writer, std::span<const double> row);
  void write(cosim::SnapshotWriter& writer, double time, const cosim::SnapshotFields& fields);

 private:
  struct HeldRow {
    cosim::TimeSeriesWriter* writer = nullptr;
    std::vector<double> values;
  };
  struct HeldField {
    std::string name;
    std::vector<double> values;
    int components = 1;
    std::string unit;
  };
  struct HeldSnapshot {
    cosim::SnapshotWriter* writer = nullptr;
    double time = 0.0;
    std::vector<HeldField> fields;
  };

  bool holding_ = false;
  // The first row_count_ rows and snapshot_count_ snapshots are held; the
  // rest is storage for the next.
  std::vector<HeldRow> rows_;
  std::size_t row_count_ = 0;
  std::vector<HeldSnapshot> snapshots_;
  std::size_t snapshot_count_ = 0;
};

}  // namespace ice

#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "cosim/io/snapshot_writer.hpp"
#include "cosim/io/time_series_writer.hpp"

namespace cosim {

// The outputs of a coupling window that may run again (implicit coupling,
// --cosim-repeat-windows): held in memory from hold() until the window is
// complete, then written in the order they were made (release(), which ends
// the holding), or dropped when the window must run again (discard(): the
// next attempt is held as well), so that a repeated window leaves no trace.
// When not holding, every output is written at once.
//
// A snapshot due inside such a window is held as a copy of its fields: the
// state it shows is gone by the window's end, and a snapshot written at once
// could not be taken back (its HDF5 file, the XDMF index). A window holds at
// most the snapshots and rows due inside it; the buffers are kept from one
// window to the next, so windows of the same outputs allocate nothing.
class HeldOutputs {
 public:
  void hold() { holding_ = true; }
  void release();
  void discard();
  bool holding() const { return holding_; }

  void append(TimeSeriesWriter& writer, std::span<const double> row);
  void write(SnapshotSink& writer, double time, const SnapshotFields& fields);

 private:
  struct HeldRow {
    TimeSeriesWriter* writer;
    std::size_t begin, size;  // in row_values_
  };
  struct HeldField {
    std::string name;
    int components = 1;
    std::string unit;
    std::vector<double> values;
  };
  struct HeldSnapshot {
    SnapshotSink* writer = nullptr;
    double time = 0.0;
    std::vector<HeldField> fields;
  };

  bool holding_ = false;
  std::vector<HeldRow> rows_;
  std::vector<double> row_values_;
  std::vector<HeldSnapshot> snapshots_;  // the first held_snapshots_ are held
  std::size_t held_snapshots_ = 0;
};

}  // namespace cosim

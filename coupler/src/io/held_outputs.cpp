#include "cosim/io/held_outputs.hpp"

namespace cosim {

void HeldOutputs::append(TimeSeriesWriter& writer, std::span<const double> row) {
  if (!holding_) {
    writer.append(row);
    return;
  }
  rows_.push_back({&writer, row_values_.size(), row.size()});
  row_values_.insert(row_values_.end(), row.begin(), row.end());
}

void HeldOutputs::write(SnapshotSink& writer, double time, const SnapshotFields& fields) {
  if (!holding_) {
    writer.write(time, fields);
    return;
  }
  if (held_snapshots_ == snapshots_.size()) snapshots_.emplace_back();
  HeldSnapshot& snapshot = snapshots_[held_snapshots_++];
  snapshot.writer = &writer;
  snapshot.time = time;
  snapshot.fields.resize(fields.size());
  auto held = snapshot.fields.begin();
  for (const auto& [name, view] : fields) {
    held->name = name;
    held->components = view.components;
    held->unit = view.unit;
    held->values.assign(view.values.begin(), view.values.end());
    ++held;
  }
}

void HeldOutputs::release() {
  holding_ = false;
  for (const HeldRow& row : rows_)
    row.writer->append(std::span<const double>(row_values_).subspan(row.begin, row.size));
  for (std::size_t k = 0; k < held_snapshots_; ++k) {
    const HeldSnapshot& snapshot = snapshots_[k];
    SnapshotFields fields;
    for (const HeldField& f : snapshot.fields)
      fields.emplace(f.name, FieldView{f.values, f.components, f.unit});
    snapshot.writer->write(snapshot.time, fields);
  }
  discard();
  holding_ = false;
}

void HeldOutputs::discard() {
  rows_.clear();
  row_values_.clear();
  held_snapshots_ = 0;
}

}  // namespace cosim

#include "ice/io/held_outputs.hpp"

namespace ice {

void HeldOutputs::append(cosim::TimeSeriesWriter& writer, std::span<const double> row) {
  if (!holding_) {
    writer.append(row);
    return;
  }
  if (row_count_ == rows_.size()) rows_.emplace_back();
  HeldRow& held = rows_[row_count_++];
  held.writer = &writer;
  held.values.assign(row.begin(), row.end());
}

void HeldOutputs::write(cosim::SnapshotWriter& writer, double time,
                        const cosim::SnapshotFields& fields) {
  if (!holding_) {
    writer.write(time, fields);
    return;
  }
  if (snapshot_count_ == snapshots_.size()) snapshots_.emplace_back();
  HeldSnapshot& held = snapshots_[snapshot_count_++];
  held.writer = &writer;
  held.time = time;
  held.fields.resize(fields.size());
  std::size_t k = 0;
  for (const auto& [name, view] : fields) {
    HeldField& field = held.fields[k++];
    field.name = name;
    field.values.assign(view.values.begin(), view.values.end());
    field.components = view.components;
    field.unit = view.unit;
  }
}

void HeldOutputs::release() {
  for (std::size_t r = 0; r < row_count_; ++r) rows_[r].writer->append(rows_[r].values);
  cosim::SnapshotFields fields;
  for (std::size_t s = 0; s < snapshot_count_; ++s) {
    const HeldSnapshot& held = snapshots_[s];
    fields.clear();
    for (const HeldField& field : held.fields)
      fields.emplace(field.name, cosim::FieldView{field.values, field.components, field.unit});
    held.writer->write(held.time, fields);
  }
  row_count_ = snapshot_count_ = 0;
  holding_ = false;
}

void HeldOutputs::discard() {
  row_count_ = snapshot_count_ = 0;
}

}  // namespace ice

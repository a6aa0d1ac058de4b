#pragma once

#include <cstddef>
#include <optional>
#include <string>

// When a coupled run writes its checkpoints (`cosim run --checkpoint-every`,
// architecture.md §14): every N accepted windows, or every T simulated
// seconds (at the first window end at or past each multiple of T).
namespace cosim::checkpoint {

class Schedule {
 public:
  // "500" (windows) or "0.5s" (simulated seconds); throws InputError naming
  // --checkpoint-every for anything else.
  static Schedule parse(const std::string& every);

  // Whether window `window` (of `length` seconds; the first is 1) ends with
  // a checkpoint. Depends on nothing but its arguments, so a restarted run
  // keeps the schedule of the run it continues.
  bool due(std::size_t window, double length) const;

  std::string describe() const;

 private:
  std::optional<std::size_t> windows_;
  std::optional<double> seconds_;
};

}  // namespace cosim::checkpoint

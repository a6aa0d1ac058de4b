#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"

// How big a run will be, estimated from its case before the solver
// allocates its arrays, and the limit every case file sets on it: a case the
// machine cannot hold is bad input, refused before it starts (exit 2 with the
// estimate), not a process that grows until the system kills it.
namespace cosim {

// One kind of item a run holds (particles, grid nodes, cells).
struct SizeCount {
  std::string name;         // plural, as printed: "particles", "grid nodes"
  double count = 0.0;       // a double: an absurd case must not overflow its own estimate
  double bytes_each = 0.0;  // measured per solver (peak RSS against count)
  double most = 0.0;        // the most the solver's index types hold
  // The key that sets the count, where a count beyond `most` is refused.
  std::optional<config::Node> set_by;
};

struct RunSize {
  std::vector<SizeCount> counts;
  double fixed_bytes = 0.0;       // what does not grow with the counts
  std::string not_included;       // what the estimate cannot know (said in summary.json)
  double memory_limit_gib = 0.0;  // the case's limits.memory_gib (set by check_run_size)

  RunSize& add(SizeCount count);
  // The count named `name`; 0 when there is none.
  double count(std::string_view name) const;
  double memory_bytes() const;
  // "123 456 particles, 20 301 grid nodes, about 0.4 GiB"
  std::string describe() const;
  // The `size` section of summary.json: one key per count ("grid nodes" as
  // grid_nodes), memory_bytes_estimate, memory_limit_bytes and not_included.
  nlohmann::json to_json() const;
};

// The `limits` mapping every case file may hold (the same keys in every
// solver's schema).
struct RunLimits {
  // Half of a 16 GB machine: far above every shipped case (the largest, at
  // full resolution, needs about 0.3 GiB), far below what a typo asks for.
  static constexpr double default_memory_gib = 8.0;
  double memory_gib = default_memory_gib;
};
config::Schema run_limits_schema();
RunLimits read_run_limits(const config::Node& case_root);

// Records the case's limit in `size` and refuses, with an InputError, a
// count beyond what the solver's indices hold (located at its key) or an
// estimate above limits.memory_gib (located at that key, or at the file
// when the case does not give it), saying the estimate and the key to raise.
void check_run_size(RunSize& size, const config::Node& case_root);

// A count as printed: digits grouped by three ("1 234 567"); an absurd one
// in scientific notation.
std::string grouped(double count);

}  // namespace cosim

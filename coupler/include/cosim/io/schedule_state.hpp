#pragma once

#include <string>

#include "cosim/io/output_schedule.hpp"
#include "cosim/io/state_file.hpp"

// An output schedule's position in a checkpoint's state file
// (`<key>.k`, `<key>.done`): a restarted run writes its outputs when the
// uninterrupted one would.
namespace cosim {

inline void write_schedule(StateFileWriter& out, const std::string& key,
                           const OutputSchedule& schedule) {
  out.number(key + ".k", schedule.position().k);
  out.integer(key + ".done", schedule.position().done ? 1 : 0);
}

inline void read_schedule(const StateFileReader& in, const std::string& key,
                          OutputSchedule& schedule) {
  schedule.resume({in.number(key + ".k"), in.integer(key + ".done") != 0});
}

}  // namespace cosim

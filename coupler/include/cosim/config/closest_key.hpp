#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cosim::config {

// The known name a mistyped one most likely meant (case-insensitive edit
// distance with transpositions, small relative to the name's length), or
// nothing when none is close: `end_tme` -> `end_time`.
std::optional<std::string> closest_key(std::string_view typed,
                                       const std::vector<std::string>& known);

// `did you mean 'end_time'?` or, when nothing is close, the list of known
// names; used to finish "unknown key" and "not one of" messages.
std::string suggestion(std::string_view typed, const std::vector<std::string>& known);

}  // namespace cosim::config

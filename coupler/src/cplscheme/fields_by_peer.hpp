#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace cosim::cplscheme {

// What the coupler sends each participant in a window: participant -> field
// -> values, shared with the messages (no copy) and the snapshot writer.
using FieldValues = std::shared_ptr<const std::vector<double>>;
using FieldsByPeer = std::map<std::string, std::map<std::string, FieldValues>>;

}  // namespace cosim::cplscheme

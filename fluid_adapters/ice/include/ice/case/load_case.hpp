#pragma once

#include <filesystem>
#include <string_view>

#include "ice/case/case_description.hpp"

namespace ice {

// Reads and checks a `kind: ice_case` file (keys: ice_case_schema()). Every
// problem is a cosim::InputError naming the file, the key path and the line:
// unknown keys, vectors of the wrong length, an empty domain, unknown or
// repeated materials, exchange pairs that do not fit, a region that misses
// the domain, a gauge outside it, boundaries that do not fit the dimension,
// bad numerics, and each equation of state's own checks.
CaseDescription load_case(const std::filesystem::path& file);
CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name);

}  // namespace ice

#pragma once

#include <filesystem>
#include <string_view>

#include "swe/case/case_description.hpp"

namespace swe {

// Reads and checks a `kind: swe_case` file (keys: swe_case_schema()). Every
// problem is a cosim::InputError naming the file, the key path and the line:
// unknown keys, cells of zero or negative width, a negative initial depth, a
// bed profile that does not cover the domain, a gauge outside the domain,
// coupling options that do not fit.
CaseDescription load_case(const std::filesystem::path& file);
CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name);

}  // namespace swe

#pragma once

#include <filesystem>
#include <string_view>

#include "openfoam/case/case_description.hpp"

namespace openfoam {

// Reads and checks a `kind: openfoam_case` file; bad input throws
// cosim::InputError naming the file, the key and the line.
CaseDescription load_case(const std::filesystem::path& file);
CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name);

}  // namespace openfoam

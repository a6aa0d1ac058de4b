#pragma once

#include <filesystem>
#include <string_view>

#include "mpm/case/case_description.hpp"

namespace mpm {

// Reads and checks a `kind: mpm_case` file (keys: mpm_case_schema()) and
// seeds its bodies. Every problem is a cosim::InputError naming the file,
// the key path and the line: unknown keys (with a suggestion), bad values,
// unknown materials or bodies, a body that seeds no particles or has
// particles outside the grid, probes outside their body, malformed
// velocity histories (located in the CSV file). Relative paths resolve from
// the file's directory.
//
// Particles get global indices in body order: body b's particles follow
// those of bodies 0..b-1 (LoadSpec::particles and ProbeSpec::particle use
// these indices).
CaseDescription load_case(const std::filesystem::path& file);
// Same, from text; `name` stands for the file in messages and paths.
CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name);

}  // namespace mpm

#pragma once

#include <filesystem>
#include <string_view>

#include "openfoam/case/case_description.hpp"

namespace openfoam {

// Reads and checks a `kind: openfoam_case` file; bad input throws
// cosim::InputError naming the file, the key and the line. `job_processes`
// > 0 is the job's `ranks` of this participant (--cosim-solver-processes):
// OpenFOAM then runs on that many processes, split as the case's
// `parallel.split` says or else by choose_split (split_given false); a case
// whose `parallel.processes` gives another count is refused.
CaseDescription load_case(const std::filesystem::path& file, int job_processes = 0);
CaseDescription load_case_text(std::string_view text, const std::filesystem::path& name,
                               int job_processes = 0);

}  // namespace openfoam

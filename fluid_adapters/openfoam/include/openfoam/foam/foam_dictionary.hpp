#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "openfoam/case/case_description.hpp"
#include "openfoam/foam/installation.hpp"

// Entries of a user's case dictionaries as OpenFOAM itself reads them,
// through its foamDictionary utility (#include, $macros, dimensioned values
// and any layout are OpenFOAM's business, not a parser of ours).
namespace openfoam {

struct DictionaryQuery {
  const Installation& installation;
  std::filesystem::path case_dir;
  std::filesystem::path log_file;  // foamDictionary's output is appended here
};

// The value of `entry` (scopes separated by '/': "water/rho") in `file`
// (relative to the case), written to 17 significant digits. A missing file
// or entry throws cosim::InputError (exit 2) naming both.
std::string dictionary_value(const DictionaryQuery& query, const std::filesystem::path& file,
                             const std::string& entry);

// Sets `entry` of `file` to `value`, adding it when missing.
void set_dictionary_entry(const DictionaryQuery& query, const std::filesystem::path& file,
                          const std::string& entry, const std::string& value);

// The number a value ends with: "1000", "[1 -3 0 0 0 0 0] 1000" and
// "rho [1 -3 0 0 0 0 0] 1000" give 1000. Anything else throws
// cosim::InputError naming the file and entry.
double scalar_value(std::string_view value, const std::filesystem::path& file,
                    const std::string& entry);
// The vector a value ends with: "(0 -9.81 0)", "[0 1 -2 0 0 0 0] ( 0 -9.81 0 )".
Vector3 vector_value(std::string_view value, const std::filesystem::path& file,
                     const std::string& entry);

}  // namespace openfoam

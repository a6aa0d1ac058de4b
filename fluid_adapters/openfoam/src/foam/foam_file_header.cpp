#include "openfoam/foam/foam_file_header.hpp"

#include <fmt/format.h>

namespace openfoam {

std::string foam_file_header(const FoamFileHeader& header) {
  std::string text = fmt::format(
      "FoamFile\n{{\n    version     2.0;\n    format      ascii;\n    class       {};\n",
      header.class_name);
  // OpenFOAM does not read the location back; it only helps a person reading the file.
  if (!header.location.empty()) text += fmt::format("    location    \"{}\";\n", header.location);
  text += fmt::format("    object      {};\n}}\n\n", header.object);
  return text;
}

}  // namespace openfoam

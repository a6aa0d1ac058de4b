#pragma once

#include <string>

// The `FoamFile` dictionary OpenFOAM expects at the top of every file it
// reads; every file the adapter writes starts with one.
namespace openfoam {

struct FoamFileHeader {
  // volScalarField, scalarField, Cloud<basicKinematicMPPICParcel>, dictionary, ...
  std::string class_name;
  // Relative to the case, e.g. "0.05/lagrangian/kinematicCloud"; empty: omitted.
  std::string location;
  // The file's name.
  std::string object;
};

// The header block, ASCII format, version 2.0, followed by a blank line.
std::string foam_file_header(const FoamFileHeader& header);

}  // namespace openfoam

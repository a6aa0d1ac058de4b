#pragma once

#include <filesystem>
#include <optional>

// How many cells a user's OpenFOAM case has, read without OpenFOAM (for the
// run's size before anything runs): what its mesh says, or what its
// blockMeshDict will make.
namespace openfoam {

// The cells of the mesh in `case_dir`: the count constant/polyMesh/owner
// states in its header (`note "... nCells:N ..."`), else the sum over the
// `hex (...) (nx ny nz)` blocks of system/blockMeshDict when every count is
// a plain number. Nothing when neither tells (no mesh yet, macros, a mesh
// made otherwise).
std::optional<double> mesh_cell_count(const std::filesystem::path& case_dir);

}  // namespace openfoam

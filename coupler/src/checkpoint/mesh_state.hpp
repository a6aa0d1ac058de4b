#pragma once

#include <string>

#include "cosim/io/state_file.hpp"
#include "cosim/mesh.hpp"

// A mesh's geometry as arrays of a state file (`<key>.kind`, `.dim`, and the
// arrays of its kind), read back bit for bit: the coupler's checkpoint keeps
// every participant's meshes as they were at the checkpoint's window end.
namespace cosim::checkpoint {

void write_mesh(StateFileWriter& out, const std::string& key, const Mesh& mesh);
Mesh read_mesh(const StateFileReader& in, const std::string& key, const std::string& name);

}  // namespace cosim::checkpoint

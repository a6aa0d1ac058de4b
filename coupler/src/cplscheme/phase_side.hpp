#pragma once

#include <map>
#include <string>
#include <vector>

#include "com/handshake.hpp"
#include "cosim/mesh.hpp"
#include "job/job.hpp"

namespace cosim::cplscheme {

// What the coupler knows of one participant in a window: its meshes (with
// versions) and the fields it wrote; what the exchange steps read.
struct PhaseSide {
  const job::ParticipantSpec* spec = nullptr;
  const com::Hello* hello = nullptr;
  const std::map<std::string, Mesh>* meshes = nullptr;
  const std::map<std::string, std::size_t>* mesh_versions = nullptr;
  const std::map<std::string, std::vector<double>>* written = nullptr;

  const Mesh& mesh(const std::string& name) const { return meshes->at(name); }
  std::size_t version(const std::string& name) const {
    auto it = mesh_versions->find(name);
    return it == mesh_versions->end() ? 0 : it->second;
  }
};

}  // namespace cosim::cplscheme

#pragma once

#include <compare>
#include <map>
#include <string>

#include "cosim/mesh.hpp"
#include "mapping/build_operator.hpp"

namespace cosim::cplscheme {

// A participant's mesh, by name.
struct MeshName {
  std::string participant;
  std::string mesh;
  friend auto operator<=>(const MeshName&, const MeshName&) = default;
};

// What determines a mapping operator: the two meshes, the constraint and the
// kernel. A field exchanged on a mesh pair and the same pair mapped by an
// exchange step (momentum_exchange, energy_exchange) share one operator.
struct OperatorKey {
  MeshName from;
  MeshName to;
  mapping::Constraint constraint = mapping::Constraint::consistent;
  mapping::Kernel kernel = mapping::Kernel::linear;
  friend auto operator<=>(const OperatorKey&, const OperatorKey&) = default;
};

// Mapping operators built once per key and rebuilt only when one of the two
// meshes changed (a new version number).
class OperatorCache {
 public:
  const mapping::Operator& get(const OperatorKey& key, const Mesh& from, std::size_t from_version,
                               const Mesh& to, std::size_t to_version);
  std::size_t builds() const { return builds_; }

 private:
  struct Entry {
    mapping::Operator op;
    std::size_t from_version = 0;
    std::size_t to_version = 0;
  };
  std::map<OperatorKey, Entry> entries_;
  std::size_t builds_ = 0;
};

}  // namespace cosim::cplscheme

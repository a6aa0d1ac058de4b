#pragma once

#include <map>
#include <string>

#include "mapping/build_operator.hpp"
#include "cosim/mesh.hpp"

namespace cosim::cplscheme {

// Mapping operators built once per mesh pair and rebuilt only when one of
// the two meshes changed (a new version number).
class OperatorCache {
 public:
  const mapping::Operator& get(const std::string& key, const Mesh& from, std::size_t from_version,
                               const Mesh& to, std::size_t to_version,
                               mapping::Constraint constraint, mapping::Kernel kernel);
  std::size_t builds() const { return builds_; }

 private:
  struct Entry {
    mapping::Operator op;
    std::size_t from_version = 0;
    std::size_t to_version = 0;
  };
  std::map<std::string, Entry> entries_;
  std::size_t builds_ = 0;
};

}  // namespace cosim::cplscheme

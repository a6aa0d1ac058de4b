#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// Constitutive models selectable by name from a case file, in the spirit of
// OpenFOAM's run-time selection tables:
//
//   materials:
//     sand: {type: mohr_coulomb, density: 2650, youngs_modulus: 1.0e7, ...}
//
// Each model registers its type name, the Schema of its parameters (which is
// also its `--help-config` documentation) and a maker. `make_material`
// validates the mapping against the schema of its `type` first, so a maker
// only sees well-formed input; physical checks the schema cannot express
// (nu < 0.5, residual angle <= peak angle) throw cosim::InputError located at
// the offending key.
class MaterialRegistry {
 public:
  using Maker = std::function<std::unique_ptr<Material>(const cosim::config::Node& parameters)>;

  static MaterialRegistry& instance();

  void add(std::string type, cosim::config::Schema schema, Maker maker);
  std::vector<std::string> types() const;
  const cosim::config::Schema& schema(const std::string& type) const;

  // `node` is the material's mapping including its `type` key. Unknown types
  // are refused with a did-you-mean suggestion.
  std::unique_ptr<Material> make(const cosim::config::Node& node) const;

  // The help listing of every registered model.
  std::string help() const;

 private:
  struct Entry {
    cosim::config::Schema schema;
    Maker maker;
  };
  std::vector<std::pair<std::string, Entry>> entries_;
};

// Adds the built-in models (linear_elastic, neo_hookean, mohr_coulomb,
// drucker_prager) to `registry`; instance() calls it once, so the models are
// present whatever the linker keeps of the static library.
void register_builtin_materials(MaterialRegistry& registry);

inline std::unique_ptr<Material> make_material(const cosim::config::Node& node) {
  return MaterialRegistry::instance().make(node);
}

}  // namespace mpm

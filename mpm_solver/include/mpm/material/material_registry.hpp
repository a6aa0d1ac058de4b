#pragma once

#include <memory>

#include "cosim/config/node.hpp"
#include "cosim/config/selection_table.hpp"
#include "mpm/material/material.hpp"

namespace mpm {

// Constitutive models selectable by name from a case file:
//
//   materials:
//     sand: {type: mohr_coulomb, density: 2650, youngs_modulus: 1.0e7, ...}
//
// Physical checks the schema cannot express (nu < 0.5, residual angle <=
// peak angle) are the makers', thrown as cosim::InputError at the key.
class MaterialRegistry : public cosim::config::SelectionTable<Material> {
 public:
  MaterialRegistry() : SelectionTable("material type", "materials.<name> with type: {}") {}
  static MaterialRegistry& instance();
};

// Adds the built-in models (linear_elastic, neo_hookean, mohr_coulomb,
// drucker_prager) to `registry`; instance() calls it once, so the models are
// present whatever the linker keeps of the static library.
void register_builtin_materials(MaterialRegistry& registry);

inline std::unique_ptr<Material> make_material(const cosim::config::Node& node) {
  return MaterialRegistry::instance().make(node);
}

}  // namespace mpm

#include "mpm/material/material_registry.hpp"

namespace mpm {

MaterialRegistry& MaterialRegistry::instance() {
  // Built-in models are added here, explicitly, so that no model depends on
  // a static initialiser surviving the static library's link.
  static MaterialRegistry registry = [] {
    MaterialRegistry r;
    register_builtin_materials(r);
    return r;
  }();
  return registry;
}

}  // namespace mpm

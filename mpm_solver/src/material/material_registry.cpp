#include "mpm/material/material_registry.hpp"

namespace mpm {

MaterialRegistry& MaterialRegistry::instance() {
  return cosim::config::builtin_table(&register_builtin_materials);
}

}  // namespace mpm

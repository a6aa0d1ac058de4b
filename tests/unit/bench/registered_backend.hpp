#pragma once

#include <stdexcept>
#include <string>

#include "bench/backend_catalog.hpp"

namespace cosim::bench::testing {

// A registered backend's descriptor (build/share/cosim/backends/<name>.yaml).
inline const BackendDescriptor& backend(const std::string& name) {
  const BackendDescriptor* b = registered_backends().find(name);
  if (b == nullptr) throw std::runtime_error("no registered backend '" + name + "'");
  return *b;
}

}  // namespace cosim::bench::testing

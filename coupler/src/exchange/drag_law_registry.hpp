#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "cosim/config/node.hpp"
#include "cosim/config/selection_table.hpp"
#include "exchange/drag_law.hpp"

namespace cosim::exchange {

// Drag laws selectable by the key `law` of a job's momentum_exchange.drag:
//
//   drag: {law: kozeny_carman, grain_size: 2.0e-4, fluid_viscosity: 1.0e-3}
//
// Each law's keys are its Schema, which `cosim help-config` lists. Checks a
// schema cannot express (exactly one of grain_size and permeability) are the
// makers', thrown as cosim::InputError at the key.
class DragLawRegistry : public config::SelectionTable<DragLaw> {
 public:
  DragLawRegistry() : SelectionTable("drag law", "momentum_exchange.drag with law: {}", "law") {}
  // Holds kozeny_carman, forchheimer, beetstra and constant.
  static DragLawRegistry& instance();
};

void register_builtin_drag_laws(DragLawRegistry& registry);

inline std::unique_ptr<DragLaw> make_drag_law(const config::Node& node) {
  return DragLawRegistry::instance().make(node);
}

// The law a YAML map selects, e.g. the drag map a job holds after loading;
// `key_path` ("momentum_exchange.drag") and `file` locate errors.
std::unique_ptr<DragLaw> make_drag_law(const YAML::Node& node, const std::string& key_path,
                                       const std::string& file = {});

}  // namespace cosim::exchange

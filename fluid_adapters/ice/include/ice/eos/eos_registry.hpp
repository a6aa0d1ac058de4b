#pragma once

#include <memory>

#include "cosim/config/node.hpp"
#include "cosim/config/selection_table.hpp"
#include "ice/eos/equation_of_state.hpp"

namespace ice {

// Equations of state selectable by name from a case file:
//
//   materials:
//     water: {eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8, ...}}
//     air:   {eos: {type: ideal_gas, gas_constant: 287.05, heat_capacity_ratio: 1.4}}
//
// Physical checks the schema cannot express are the makers', thrown as
// cosim::InputError at the key.
class EosRegistry : public cosim::config::SelectionTable<EquationOfState> {
 public:
  EosRegistry() : SelectionTable("equation of state", "eos with type: {}") {}
  static EosRegistry& instance();
};

// Adds ideal_gas and linear_water; instance() calls it once.
void register_builtin_equations_of_state(EosRegistry& registry);

inline std::unique_ptr<EquationOfState> make_equation_of_state(const cosim::config::Node& node) {
  return EosRegistry::instance().make(node);
}

}  // namespace ice

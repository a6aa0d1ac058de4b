#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "ice/eos/equation_of_state.hpp"

namespace ice {

// Equations of state selectable by name from a case file:
//
//   materials:
//     water: {eos: {type: linear_water, bulk_modulus: 2.15e9, reference_density: 999.8, ...}}
//     air:   {eos: {type: ideal_gas, gas_constant: 287.05, heat_capacity_ratio: 1.4}}
//
// Each model registers its type name, the Schema of its parameters (its
// `--help-config` documentation) and a maker. `make` validates the mapping
// against the schema of its `type` first; physical checks the schema cannot
// express throw cosim::InputError located at the offending key.
class EosRegistry {
 public:
  using Maker = std::function<std::unique_ptr<EquationOfState>(const cosim::config::Node& parameters)>;

  static EosRegistry& instance();

  void add(std::string type, cosim::config::Schema schema, Maker maker);
  std::vector<std::string> types() const;
  const cosim::config::Schema& schema(const std::string& type) const;

  // `node` is the model's mapping including its `type` key. Unknown types
  // are refused with a did-you-mean suggestion.
  std::unique_ptr<EquationOfState> make(const cosim::config::Node& node) const;

  std::string help() const;

 private:
  struct Entry {
    cosim::config::Schema schema;
    Maker maker;
  };
  std::vector<std::pair<std::string, Entry>> entries_;
};

// Adds ideal_gas and linear_water; instance() calls it once.
void register_builtin_equations_of_state(EosRegistry& registry);

inline std::unique_ptr<EquationOfState> make_equation_of_state(const cosim::config::Node& node) {
  return EosRegistry::instance().make(node);
}

}  // namespace ice

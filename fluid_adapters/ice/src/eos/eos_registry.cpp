#include "ice/eos/eos_registry.hpp"

#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"

namespace ice {

EosRegistry& EosRegistry::instance() {
  return cosim::config::builtin_table(&register_builtin_equations_of_state);
}

void register_builtin_equations_of_state(EosRegistry& registry) {
  registry.add(std::string(IdealGas::name), IdealGas::schema(), &IdealGas::make);
  registry.add(std::string(LinearWater::name), LinearWater::schema(), &LinearWater::make);
}

}  // namespace ice

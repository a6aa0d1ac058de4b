#include "mpm/material/drucker_prager.hpp"
#include "mpm/material/linear_elastic.hpp"
#include "mpm/material/material_registry.hpp"
#include "mpm/material/mohr_coulomb.hpp"
#include "mpm/material/neo_hookean.hpp"

namespace mpm {

void register_builtin_materials(MaterialRegistry& registry) {
  registry.add(std::string(LinearElastic::name), LinearElastic::schema(), &LinearElastic::make);
  registry.add(std::string(NeoHookean::name), NeoHookean::schema(), &NeoHookean::make);
  registry.add(std::string(MohrCoulomb::name), MohrCoulomb::schema(), &MohrCoulomb::make);
  registry.add(std::string(DruckerPrager::name), DruckerPrager::schema(), &DruckerPrager::make);
}

}  // namespace mpm

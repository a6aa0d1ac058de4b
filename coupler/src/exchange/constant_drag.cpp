#include "exchange/constant_drag.hpp"

#include "exchange/drag_law_keys.hpp"

namespace cosim::exchange {

config::Schema ConstantDrag::schema() {
  config::Schema schema = drag_law_keys::base_schema(
      law,
      "A fixed K: 1e15 couples a fluid to an impermeable structure, 1e5 two fluids (Tran et al., "
      "MPMICE, items 2 and 4 after eq. 33).");
  schema.required("coefficient", config::Schema::number().positive().unit("kg/(m^3 s)"),
                  "The drag coefficient K.");
  return schema;
}

std::unique_ptr<DragLaw> ConstantDrag::make(const config::Node& node) {
  return std::make_unique<ConstantDrag>(node["coefficient"].as<double>());
}

}  // namespace cosim::exchange

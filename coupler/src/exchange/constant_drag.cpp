#include "exchange/constant_drag.hpp"

#include "builtin_drag_laws.hpp"

namespace cosim::exchange::detail {

std::unique_ptr<DragLaw> make_constant_drag(DragParameters& parameters) {
  return std::make_unique<ConstantDrag>(parameters.positive("coefficient"));
}

}  // namespace cosim::exchange::detail

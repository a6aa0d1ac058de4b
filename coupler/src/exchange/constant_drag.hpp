#pragma once

#include <memory>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "exchange/drag_law.hpp"

namespace cosim::exchange {

// A fixed K: 1e15 couples a fluid to an impermeable structure, 1e5 couples
// two fluids (Tran et al., MPMICE, items 2 and 4 after eq. 33).
// YAML: {law: constant, coefficient: <kg m^-3 s^-1>}.
class ConstantDrag final : public DragLaw {
 public:
  static constexpr std::string_view law = "constant";
  static config::Schema schema();
  static std::unique_ptr<DragLaw> make(const config::Node& node);

  explicit ConstantDrag(double coefficient) : coefficient_(coefficient) {}

  std::string_view name() const override { return law; }
  double coefficient(const DragInput&) const override { return coefficient_; }

 private:
  double coefficient_;
};

}  // namespace cosim::exchange

#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "exchange/drag_law.hpp"

namespace cosim::exchange {

// Kozeny–Carman drag, linear in the relative velocity (Darcy flow):
//   from the grain size D_p:      K = 180 phi_s^2 mu_f / (D_p^2 (1 - phi_s))  (Tran et al., eq. 29)
//   from the permeability kappa:  K = n^2 mu_f / kappa                        (Tran et al., eq. 30)
// YAML: {law: kozeny_carman, fluid_viscosity: <Pa s>, grain_size: <m> | permeability: <m^2>},
// where either length may be the word `field` to read it per cell.
class KozenyCarman final : public DragLaw {
 public:
  static constexpr std::string_view law = "kozeny_carman";
  static config::Schema schema();
  static std::unique_ptr<DragLaw> make(const config::Node& node);

  enum class Basis { grain_size, permeability };

  // `value` is D_p [m] or kappa [m^2]; nullopt reads it per cell.
  KozenyCarman(double fluid_viscosity, Basis basis, std::optional<double> value);

  std::string_view name() const override { return law; }
  double coefficient(const DragInput& input) const override;
  CellInput cell_input() const override;

 private:
  double fluid_viscosity_;
  Basis basis_;
  std::optional<double> value_;
};

}  // namespace cosim::exchange

#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "exchange/drag_law.hpp"

namespace cosim::exchange {

// Low-Reynolds limit F(phi_s, 0) (Tran et al., MPMICE, eq. 28).
double beetstra_f0(double solid_fraction);
// F(phi_s, Re) (Tran et al., eq. 27), finite and continuous at Re = 0.
double beetstra_f(double solid_fraction, double reynolds);

// Drag fitted to simulations of flow through sphere packings,
// 0.1 < phi_s < 0.6 and Re < 1000 (Tran et al., eqs. 25–28):
//   K  = 18 phi_s (1 - phi_s) mu_f / D_p^2 F(phi_s, Re),
//   Re = n rho_f D_p |U_s - U_f| / mu_f                    (eq. 26).
// YAML: {law: beetstra, fluid_viscosity: <Pa s>, grain_size: <m> | field}.
class Beetstra final : public DragLaw {
 public:
  static constexpr std::string_view law = "beetstra";
  static config::Schema schema();
  static std::unique_ptr<DragLaw> make(const config::Node& node);

  Beetstra(double fluid_viscosity, std::optional<double> grain_size);

  std::string_view name() const override { return law; }
  double coefficient(const DragInput& input) const override;
  CellInput cell_input() const override;

 private:
  double fluid_viscosity_;
  std::optional<double> grain_size_;
};

}  // namespace cosim::exchange

#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "exchange/drag_law.hpp"

namespace cosim::exchange {

// Intrinsic permeability from the mean grain size (Pan et al. 2021, eq. 4):
//   k = D50^2 n^3 / (150 (1 - n)^2)   [m^2]
double kozeny_carman_permeability(double d50, double porosity);

// Forchheimer drag, nonlinear in |U_f - U_s| (Pan et al. 2021, eq. 3):
//   K = n^2 (mu_f / k + 1.75 rho_f |U_f - U_s| / (sqrt(150 k) n^(3/2)))
// with k configured, read per cell, or from D50 through eq. 4.
// YAML: {law: forchheimer, fluid_viscosity: <Pa s>, grain_size: <m> | permeability: <m^2>},
// either length may be `field`.
class Forchheimer final : public DragLaw {
 public:
  static constexpr std::string_view law = "forchheimer";
  static config::Schema schema();
  static std::unique_ptr<DragLaw> make(const config::Node& node);

  enum class Basis { grain_size, permeability };

  Forchheimer(double fluid_viscosity, Basis basis, std::optional<double> value);

  std::string_view name() const override { return law; }
  double coefficient(const DragInput& input) const override;
  CellInput cell_input() const override;

 private:
  double fluid_viscosity_;
  Basis basis_;
  std::optional<double> value_;
};

}  // namespace cosim::exchange

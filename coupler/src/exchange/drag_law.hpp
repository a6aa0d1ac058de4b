#pragma once

#include <string_view>

// Drag-coefficient laws for the momentum exchange between a fluid and a
// porous solid (architecture.md §4). A law gives K [kg m^-3 s^-1] such that the drag
// on the fluid per unit mixture volume is f_d = K (U_s - U_f) (Tran et al.,
// MPMICE, eq. 24); the solid receives -f_d.
namespace cosim::exchange {

// What a law may read in one cell. Nonlinear laws (Forchheimer, Beetstra) are
// evaluated with the lagged relative speed |U*_s - U*_f| of the velocities
// entering the exchange, so that K is fixed during the implicit solve.
struct DragInput {
  double solid_fraction = 0;  // phi_s = 1 - n [-]
  double fluid_density = 0;   // true (intrinsic) fluid density rho_f [kg m^-3]
  double relative_speed = 0;  // |U_s - U_f| [m s^-1]
  double grain_size = 0;      // D_p or D50 [m], only read by laws given 'grain_size: field'
  double permeability = 0;    // intrinsic permeability kappa [m^2], 'permeability: field'
};

// The per-cell field a law reads instead of a configured constant.
enum class CellInput { none, grain_size, permeability };

class DragLaw {
 public:
  virtual ~DragLaw() = default;
  virtual std::string_view name() const = 0;
  // K >= 0 [kg m^-3 s^-1]; +infinity when the cell holds no pore space.
  virtual double coefficient(const DragInput& input) const = 0;
  virtual CellInput cell_input() const { return CellInput::none; }
};

}  // namespace cosim::exchange

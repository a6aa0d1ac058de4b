#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace YAML {
class Node;
}

// Drag-coefficient laws for the momentum exchange between a fluid and a
// porous solid (architecture.md §4). A law gives K [kg m^-3 s^-1] such that the drag
// on the fluid per unit mixture volume is f_d = K (U_s - U_f) (Tran et al.,
// MPMICE, eq. 24); the solid receives -f_d.
namespace cosim::exchange {

class DragParameters;

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

using DragLawFactory = std::function<std::unique_ptr<DragLaw>(DragParameters&)>;

// Adds a law to the registry under `name` (replacing one of the same name).
// The built-in laws kozeny_carman, forchheimer, beetstra and constant are
// always present.
void register_drag_law(const std::string& name, DragLawFactory factory);
std::vector<std::string> drag_law_names();

// Builds the law a YAML map selects with its key `law`, e.g.
//   {law: kozeny_carman, grain_size: 2.0e-4, fluid_viscosity: 1.0e-3}
// `key_path` (e.g. "momentum_exchange.drag") and `file` locate errors: an
// unknown law, a missing, non-positive or unknown key throws cosim::InputError
// naming the key.
std::unique_ptr<DragLaw> make_drag_law(const YAML::Node& node, const std::string& key_path,
                                       const std::string& file = {});

}  // namespace cosim::exchange

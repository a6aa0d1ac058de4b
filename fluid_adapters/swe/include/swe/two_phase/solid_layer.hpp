#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace swe {

// The solids of a landslide or debris flow as the 2D shallow water sees them,
// per cell of its grid (cells numbered x fastest): phase c of van den Bout et
// al., OpenLISEM Hazard (solids with the fluid they confine), whose material
// points live in another process. The free fluid (phase u) of the shallow
// water flows over bed + depth; the mixture's depth is H = h_s + h_f, with
// alpha_c = h_s / H and alpha_u = h_f / H.
//
// The fluid holds the solids' velocity over a coupling window (as ICE does):
// the two-phase exchange relaxes it against the fluid's and accumulates the
// impulse the solids receive, which the coupler hands to the particles.
struct SolidLayer {
  std::vector<double> depth;             // h_s [m], >= 0
  std::vector<double> velocity_x;        // u_s [m/s]
  std::vector<double> velocity_y;        // v_s [m/s] (zeros in 1D)
  std::vector<double> density;           // rho_c, bulk density of phase c [kg/m^3]
  std::vector<double> structured_share;  // f_sc: share of the solids bound in blocks [-]
  // d of the unconfined grains per cell [m]; empty: the drag parameters' grain size.
  std::vector<double> grain_size;
  // Fluid the solids release (fragmented structures, van den Bout et al.,
  // OpenLISEM Hazard, eq. 27) [m^3/s per cell]: the coupler's volume per
  // window divided by the window. Empty: none.
  std::vector<double> released_fluid_rate;

  std::size_t size() const { return depth.size(); }
};

// A layer of `cells` cells without solids: zero depth and velocity, the given
// density, no structures.
SolidLayer empty_solid_layer(std::size_t cells, double density);

// What a depth-averaged mass's columns put on each cell (summed by the
// coupler, conservatively): volume V [m^3], mass m [kg], momentum m u
// [kg m/s] (x and y of a cell side by side), the mass still bound in blocks
// f_sc m [kg], and the fluid released over the window [m^3].
struct ColumnTotals {
  std::span<const double> volume, mass, momentum, structured_mass, released_volume;
};

// The layer of those columns over cells of `cell_area` [m^2]: h_s = V / |cell|,
// rho_c = m / V, u_s = m u / m, f_sc = f_sc m / m (clamped to [0, 1] against
// round-off), and the released fluid as a rate over `window` [s]. A cell
// without columns (V <= 0) holds no solids, at `empty_density`. Throws
// cosim::InputError for arrays of other sizes or a layer that fails
// validate() (a negative volume, a non-finite value).
SolidLayer layer_from_columns(const ColumnTotals& columns, std::size_t cells, double cell_area,
                              double window, double empty_density);

// Throws cosim::InputError naming the cell and the quantity for: an array
// whose size is not `cells` (grain_size and released_fluid_rate may be
// empty), a non-finite value, a negative depth or released-fluid rate, a
// non-positive density or grain size, a structured share outside [0, 1].
void validate(const SolidLayer& layer, std::size_t cells);

}  // namespace swe

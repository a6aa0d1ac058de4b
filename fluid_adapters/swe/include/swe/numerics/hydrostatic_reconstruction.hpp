#pragma once

#include <algorithm>

namespace swe {

// Hydrostatic reconstruction at a face (Audusse, Bouchut, Bristeau, Klein &
// Perthame, SIAM J. Sci. Comput. 25, 2004): from the reconstructed depth and
// bed on each side, the depths seen by the Riemann solver are measured from
// the higher bed,
//   B* = max(B_l, B_r),   h*_l = max(0, h_l + B_l - B*),   h*_r = max(0, h_r + B_r - B*),
// and each side adds the pressure difference g/2 (h^2 - h*^2) to the normal
// momentum flux it sees. With the centred source of a reconstructed cell
// (see cell_bed_source) this discretises -g h dB/dx so that a lake at rest,
// dry emerged parts included, is preserved exactly and depths stay
// non-negative. It is the well-balanced split of the bed source into its
// face parts and its in-cell part, as in Zheng et al., eqs. 33-34.
struct HydrostaticFace {
  double h_left = 0.0;            // h*_l
  double h_right = 0.0;           // h*_r
  double left_correction = 0.0;   // g/2 (h_l^2 - h*_l^2): added to the flux the left cell sees
  double right_correction = 0.0;  // g/2 (h_r^2 - h*_r^2): added to the flux the right cell sees
};

inline HydrostaticFace hydrostatic_face(double h_l, double bed_l, double h_r, double bed_r,
                                        double g) {
  const double bed = std::max(bed_l, bed_r);
  HydrostaticFace f;
  f.h_left = std::max(0.0, h_l + bed_l - bed);
  f.h_right = std::max(0.0, h_r + bed_r - bed);
  f.left_correction = 0.5 * g * (h_l * h_l - f.h_left * f.h_left);
  f.right_correction = 0.5 * g * (h_r * h_r - f.h_right * f.h_right);
  return f;
}

// The bed source inside a reconstructed cell [momentum per unit length of the
// face-normal direction, times the cell width]: -g (h_minus + h_plus)/2 (B_plus - B_minus),
// where minus/plus are the reconstructed values at the cell's lower and upper
// faces. Zero for a first-order (flat) reconstruction.
inline double cell_bed_source(double h_minus, double bed_minus, double h_plus, double bed_plus,
                              double g) {
  return -0.5 * g * (h_minus + h_plus) * (bed_plus - bed_minus);
}

}  // namespace swe

#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ice {

// Gradient limiter of the advected profile in the donor cell, chosen by name
// in a case file:
//   first_order  the donor cell's value (no gradient): first-order upwind;
//   minmod       the smaller of the two one-sided differences;
//   van_leer     their harmonic mean (van Leer 1974), second order on smooth
//                data and sharper than minmod at discontinuities.
// Both limited profiles are zero at an extremum and keep the face value
// between the donor's neighbours (Sweby's TVD region).
enum class Limiter : std::uint8_t { first_order, minmod, van_leer };

// Throws cosim::InputError naming the known limiters (with a did-you-mean).
Limiter limiter_from_name(std::string_view name);
std::string_view to_string(Limiter limiter);
std::vector<std::string> limiter_names();

// The limited difference of a cell from its one-sided differences
// a = q_c - q_{c-1} and b = q_{c+1} - q_c, branch-free for vectorised loops.
template <Limiter limiter>
inline double limited_difference(double a, double b) {
  if constexpr (limiter == Limiter::first_order) {
    return 0.0;
  } else if constexpr (limiter == Limiter::minmod) {
    const double smaller = std::abs(a) < std::abs(b) ? a : b;
    return a * b > 0.0 ? smaller : 0.0;
  } else {
    // The division is done whatever the sign (a + b may then be 0: the
    // quotient is discarded), so that the choice is a select the compiler
    // can vectorise; a conditional division it must keep as a branch, which
    // rough data mispredicts.
    const double product = a * b;
    const double harmonic = 2.0 * product / (a + b);
    return product > 0.0 ? harmonic : 0.0;
  }
}

}  // namespace ice

#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace swe {

// Numerical flux at a face. Zheng et al. use Roe's (eqs. 30-32); HLL and
// HLLC are positivity-preserving. Roe falls back to HLL at a face with a dry
// side, where Roe's linearisation can produce negative depths.
enum class FluxKind : std::uint8_t { roe, hll, hllc };

// Slope limiter of the MUSCL reconstruction; `none` gives first order.
enum class LimiterKind : std::uint8_t { none, minmod, van_leer, monotonized_central };

struct Scheme {
  FluxKind flux = FluxKind::hllc;
  LimiterKind limiter = LimiterKind::van_leer;
  // Courant number C_r of the step (Zheng et al., eq. 37). Second-order
  // hydrostatic reconstruction keeps depths non-negative for C_r <= 0.5.
  double courant = 0.5;
};

// The names a case file gives them: to_string of every kind, in the order
// of the enumeration, and back (std::invalid_argument for another name).
const char* to_string(FluxKind kind);
const char* to_string(LimiterKind kind);
std::vector<std::string> flux_names();
std::vector<std::string> limiter_names();
FluxKind flux_from_string(std::string_view name);
LimiterKind limiter_from_string(std::string_view name);

}  // namespace swe

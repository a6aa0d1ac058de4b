#pragma once

#include <cstdint>
#include <string_view>

namespace swe {

// Conditions on a domain face, imposed through two ghost cells. The first
// ghost's bed equals the adjacent interior cell's, so there is no bed step
// at the face (2D walls mirror the interior's bed in both ghosts).
enum class BoundaryKind : std::uint8_t {
  wall,              // reflective: ghost mirrors the interior, normal velocity negated
  transmissive,      // zero gradient: ghost copies the interior
  inflow_discharge,  // prescribed normal discharge q [m^2/s] into the domain; depth from the
                     // interior
  fixed_depth,       // prescribed depth [m]; velocity from the outgoing Riemann invariant
};

struct Boundary {
  BoundaryKind kind = BoundaryKind::wall;
  // inflow_discharge: discharge per unit width entering the domain [m^2/s];
  // fixed_depth: depth [m]. Unused otherwise.
  double value = 0.0;
};

const char* to_string(BoundaryKind kind);

}  // namespace swe

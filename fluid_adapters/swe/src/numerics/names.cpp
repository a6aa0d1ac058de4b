#include "swe/boundary.hpp"
#include "swe/scheme.hpp"

namespace swe {

const char* to_string(BoundaryKind kind) {
  switch (kind) {
    case BoundaryKind::wall:
      return "wall";
    case BoundaryKind::transmissive:
      return "transmissive";
    case BoundaryKind::inflow_discharge:
      return "inflow_discharge";
    case BoundaryKind::fixed_depth:
      return "fixed_depth";
  }
  return "?";
}

const char* to_string(FluxKind kind) {
  switch (kind) {
    case FluxKind::roe:
      return "roe";
    case FluxKind::hll:
      return "hll";
    case FluxKind::hllc:
      return "hllc";
  }
  return "?";
}

const char* to_string(LimiterKind kind) {
  switch (kind) {
    case LimiterKind::none:
      return "none";
    case LimiterKind::minmod:
      return "minmod";
    case LimiterKind::van_leer:
      return "van_leer";
    case LimiterKind::monotonized_central:
      return "monotonized_central";
  }
  return "?";
}

}  // namespace swe

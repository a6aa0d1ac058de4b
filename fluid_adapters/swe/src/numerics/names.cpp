#include <array>
#include <stdexcept>

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

namespace {

constexpr std::array flux_kinds{FluxKind::roe, FluxKind::hll, FluxKind::hllc};
constexpr std::array limiter_kinds{LimiterKind::none, LimiterKind::minmod, LimiterKind::van_leer,
                                   LimiterKind::monotonized_central};

template <class Kind, std::size_t N>
std::vector<std::string> names_of(const std::array<Kind, N>& kinds) {
  std::vector<std::string> names;
  for (const Kind kind : kinds) names.emplace_back(to_string(kind));
  return names;
}

template <class Kind, std::size_t N>
Kind kind_named(const std::array<Kind, N>& kinds, std::string_view name, const char* what) {
  for (const Kind kind : kinds)
    if (name == to_string(kind)) return kind;
  throw std::invalid_argument("unknown " + std::string(what) + " '" + std::string(name) + "'");
}

}  // namespace

std::vector<std::string> flux_names() {
  return names_of(flux_kinds);
}
std::vector<std::string> limiter_names() {
  return names_of(limiter_kinds);
}
FluxKind flux_from_string(std::string_view name) {
  return kind_named(flux_kinds, name, "flux");
}
LimiterKind limiter_from_string(std::string_view name) {
  return kind_named(limiter_kinds, name, "limiter");
}

}  // namespace swe

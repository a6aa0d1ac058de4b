#include "ice/advection/limiter.hpp"

#include <string>

#include "cosim/config/closest_key.hpp"
#include "cosim/error.hpp"

namespace ice {

std::vector<std::string> limiter_names() {
  return {"first_order", "minmod", "van_leer"};
}

std::string_view to_string(Limiter limiter) {
  switch (limiter) {
    case Limiter::first_order:
      return "first_order";
    case Limiter::minmod:
      return "minmod";
    case Limiter::van_leer:
      return "van_leer";
  }
  return "?";
}

Limiter limiter_from_name(std::string_view name) {
  for (const Limiter limiter : {Limiter::first_order, Limiter::minmod, Limiter::van_leer}) {
    if (to_string(limiter) == name) {
      return limiter;
    }
  }
  throw cosim::InputError("unknown advection limiter '" + std::string(name) + "'; " +
                          cosim::config::suggestion(name, limiter_names()));
}

}  // namespace ice

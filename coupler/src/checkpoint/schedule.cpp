#include "checkpoint/schedule.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "cosim/error.hpp"

namespace cosim::checkpoint {

namespace {

[[noreturn]] void refuse(const std::string& every, const std::string& why) {
  throw InputError(
      fmt::format("--checkpoint-every '{}': {} (a count of windows such as 500, or "
                  "simulated seconds such as 0.5s)",
                  every, why));
}

// Windows ending within this fraction of a window past a multiple of T
// still count as reaching it.
constexpr double time_tolerance = 1e-9;

}  // namespace

Schedule Schedule::parse(const std::string& every) {
  Schedule s;
  if (every.empty()) refuse(every, "empty");
  const bool in_seconds = every.back() == 's';
  const std::string number = in_seconds ? every.substr(0, every.size() - 1) : every;
  std::size_t used = 0;
  try {
    if (in_seconds) {
      const double t = std::stod(number, &used);
      if (used != number.size()) refuse(every, "not a number of seconds");
      if (!(t > 0.0) || !std::isfinite(t)) refuse(every, "not a positive time");
      s.seconds_ = t;
    } else {
      if (number.find_first_not_of("0123456789") != std::string::npos)
        refuse(every, "not a whole number of windows");
      const unsigned long long n = std::stoull(number, &used);
      if (n == 0) refuse(every, "zero windows");
      s.windows_ = static_cast<std::size_t>(n);
    }
  } catch (const std::logic_error&) {
    refuse(every, "not a number");
  }
  return s;
}

bool Schedule::due(std::size_t window, double length) const {
  if (window == 0) return false;
  if (windows_) return window % *windows_ == 0;
  // The window's end and the one before it, on either side of a multiple of T.
  const auto multiples = [&](std::size_t w) {
    const double elapsed = static_cast<double>(w) * length;
    return std::floor(elapsed / *seconds_ + time_tolerance * length / *seconds_);
  };
  return multiples(window) > multiples(window - 1);
}

std::string Schedule::describe() const {
  return windows_ ? fmt::format("every {} windows", *windows_)
                  : fmt::format("every {} s of simulated time", *seconds_);
}

}  // namespace cosim::checkpoint

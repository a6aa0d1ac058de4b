#include "cosim/io/phase_timer.hpp"

namespace cosim {

PhaseTimer::Scope::Scope(PhaseTimer& timer, std::string_view phase)
    : timer_(timer), phase_(phase), start_(Clock::now()) {}

PhaseTimer::Scope::~Scope() {
  timer_.add(phase_, std::chrono::duration<double>(Clock::now() - start_).count());
}

void PhaseTimer::add(std::string_view phase, double seconds) {
  auto it = seconds_.find(phase);
  if (it == seconds_.end()) it = seconds_.emplace(std::string(phase), 0.0).first;
  it->second += seconds;
}

double PhaseTimer::seconds(std::string_view phase) const {
  const auto it = seconds_.find(phase);
  return it == seconds_.end() ? 0.0 : it->second;
}

double PhaseTimer::total_seconds() const {
  double total = 0.0;
  for (const auto& [phase, s] : seconds_) total += s;
  return total;
}

}  // namespace cosim

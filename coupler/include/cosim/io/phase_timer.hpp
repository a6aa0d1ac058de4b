#pragma once

#include <chrono>
#include <map>
#include <string>
#include <string_view>

namespace cosim {

// Wall time accumulated per named phase ("advance", "mapping", "output"...).
class PhaseTimer {
 public:
  using Clock = std::chrono::steady_clock;

  // Adds the time from construction to destruction to its phase.
  class Scope {
   public:
    Scope(PhaseTimer& timer, std::string_view phase);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseTimer& timer_;
    std::string phase_;
    Clock::time_point start_;
  };

  [[nodiscard]] Scope measure(std::string_view phase) { return Scope(*this, phase); }
  void add(std::string_view phase, double seconds);
  double seconds(std::string_view phase) const;  // 0 for a phase never measured
  double total_seconds() const;
  const std::map<std::string, double, std::less<>>& phases() const { return seconds_; }

 private:
  std::map<std::string, double, std::less<>> seconds_;
};

}  // namespace cosim

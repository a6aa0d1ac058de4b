#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

// Martin & Moyce's (1952) surge front, Z = x_front / a against
// T = t sqrt(2 g / a), and how a simulated front compares with it: the
// largest relative error for T <= 3, the time offset that fits best, and the
// front speed over the propagation phase. Shared by the fluid backends'
// validations, so they are compared on one measure.
namespace cosim::testing::martin_moyce {

struct Point {
  double time, value;
};

inline constexpr double column_width = 0.05715;  // a [m]
inline double time_scale(double g = 9.81) {
  return std::sqrt(2.0 * g / column_width);
}

// The `front,T,Z` rows of the reference CSV.
inline std::vector<Point> experiment_front(const std::string& csv) {
  std::ifstream in(csv);
  std::vector<Point> points;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("front,", 0) != 0) continue;
    std::istringstream fields(line.substr(6));
    Point p{};
    char comma = 0;
    fields >> p.time >> comma >> p.value;
    points.push_back(p);
  }
  return points;
}

struct Comparison {
  double largest_error = 0.0;         // raw, T <= 3
  double offset = 0.0;                // the time offset that fits best, in T
  double largest_error_offset = 0.0;  // with it
  double simulated_speed = 0.0;       // dZ/dT between the first and last points, 1.4 <= T <= 3
  double measured_speed = 0.0;
};

// `front` (T ascending, from T = 0) interpolated linearly.
class SurgeFront {
 public:
  explicit SurgeFront(std::vector<Point> front) : front_(std::move(front)) {}

  double at(double time) const {
    if (time <= front_.front().time) return front_.front().value;
    std::size_t k = 1;
    while (k + 1 < front_.size() && front_[k].time < time) ++k;
    const double w = (time - front_[k - 1].time) / (front_[k].time - front_[k - 1].time);
    return front_[k - 1].value + w * (front_[k].value - front_[k - 1].value);
  }

  double largest_error(const std::vector<Point>& measured, double offset) const {
    double worst = 0.0;
    for (const Point& p : measured) {
      if (p.time <= 3.0) worst = std::max(worst, std::abs(at(p.time - offset) / p.value - 1.0));
    }
    return worst;
  }

  // Prints each measured point beside the simulated front.
  Comparison compare(const std::vector<Point>& measured) const {
    for (const Point& p : measured) {
      if (p.time > 3.0) continue;
      fmt::print("T = {:.2f}: front {:.3f} vs experiment {:.2f} ({:+.1f} %)\n", p.time, at(p.time),
                 p.value, 100.0 * (at(p.time) / p.value - 1.0));
    }
    Comparison c;
    c.largest_error = largest_error(measured, 0.0);
    for (double trial = 0.0; trial <= 0.6; trial += 0.005) {
      if (largest_error(measured, trial) < largest_error(measured, c.offset)) c.offset = trial;
    }
    c.largest_error_offset = largest_error(measured, c.offset);
    const Point* first = nullptr;
    const Point* last = nullptr;
    for (const Point& p : measured) {
      if (p.time < 1.4 || p.time > 3.0) continue;
      if (first == nullptr) first = &p;
      last = &p;
    }
    if (first != nullptr && last != first) {
      c.measured_speed = (last->value - first->value) / (last->time - first->time);
      c.simulated_speed = (at(last->time) - at(first->time)) / (last->time - first->time);
    }
    return c;
  }

 private:
  std::vector<Point> front_;
};

}  // namespace cosim::testing::martin_moyce

#include "bench/gas_riemann_problem.hpp"

#include <cmath>
#include <stdexcept>

namespace cosim::bench {

ExactRiemannSolution::ExactRiemannSolution(GasState left, GasState right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  if (!(gamma > 1.0) || !(left.density > 0.0) || !(right.density > 0.0) || !(left.pressure > 0.0) ||
      !(right.pressure > 0.0)) {
    throw std::invalid_argument("exact Riemann: densities, pressures must be > 0 and gamma > 1");
  }
  sound_left_ = std::sqrt(gamma * left.pressure / left.density);
  sound_right_ = std::sqrt(gamma * right.pressure / right.density);
  // Toro eq. 4.40: the pressure positivity condition.
  const double du = right.velocity - left.velocity;
  if (2.0 * (sound_left_ + sound_right_) / (gamma - 1.0) <= du) {
    throw std::invalid_argument("exact Riemann: the states generate a vacuum");
  }
  // Two-rarefaction guess (Toro eq. 4.46), then Newton on f(p) = f_L + f_R + du.
  const double z = (gamma - 1.0) / (2.0 * gamma);
  double p = std::pow(
      (sound_left_ + sound_right_ - 0.5 * (gamma - 1.0) * du) /
          (sound_left_ / std::pow(left.pressure, z) + sound_right_ / std::pow(right.pressure, z)),
      1.0 / z);
  p = std::max(p, 1e-12 * std::min(left.pressure, right.pressure));
  for (int iteration = 0; iteration < 100; ++iteration) {
    double d_left = 0.0, d_right = 0.0;
    const double f = pressure_function(p, left_, sound_left_, d_left) +
                     pressure_function(p, right_, sound_right_, d_right) + du;
    double next = p - f / (d_left + d_right);
    if (next <= 0.0) next = 0.5 * p;
    const double change = 2.0 * std::abs(next - p) / (next + p);
    p = next;
    if (change < 1e-14) break;
  }
  star_pressure_ = p;
  double d = 0.0;
  star_velocity_ = 0.5 * (left.velocity + right.velocity) +
                   0.5 * (pressure_function(p, right_, sound_right_, d) -
                          pressure_function(p, left_, sound_left_, d));
}

double ExactRiemannSolution::pressure_function(double p, const GasState& state, double sound_speed,
                                               double& derivative) const {
  const double g = gamma_;
  if (p > state.pressure) {  // shock, Toro eq. 4.21
    const double a = 2.0 / ((g + 1.0) * state.density);
    const double b = (g - 1.0) / (g + 1.0) * state.pressure;
    const double root = std::sqrt(a / (p + b));
    derivative = root * (1.0 - 0.5 * (p - state.pressure) / (p + b));
    return (p - state.pressure) * root;
  }
  // rarefaction, Toro eq. 4.26
  const double ratio = p / state.pressure;
  derivative = std::pow(ratio, -(g + 1.0) / (2.0 * g)) / (state.density * sound_speed);
  return 2.0 * sound_speed / (g - 1.0) * (std::pow(ratio, (g - 1.0) / (2.0 * g)) - 1.0);
}

GasState ExactRiemannSolution::sample(double s) const {
  const double g = gamma_;
  const double p = star_pressure_, u = star_velocity_;
  // Toro section 4.5: the side of the contact, then shock or fan.
  const bool left_side = s <= u;
  const GasState& k = left_side ? left_ : right_;
  const double c = left_side ? sound_left_ : sound_right_;
  const double sign = left_side ? 1.0 : -1.0;  // left waves move with u - c
  const double pk = p / k.pressure;
  if (p > k.pressure) {
    const double shock =
        k.velocity - sign * c * std::sqrt((g + 1.0) / (2.0 * g) * pk + (g - 1.0) / (2.0 * g));
    if (sign * (s - shock) <= 0.0) return k;
    const double ratio = (pk + (g - 1.0) / (g + 1.0)) / ((g - 1.0) / (g + 1.0) * pk + 1.0);
    return {k.density * ratio, u, p};
  }
  const double head = k.velocity - sign * c;
  const double c_star = c * std::pow(pk, (g - 1.0) / (2.0 * g));
  const double tail = u - sign * c_star;
  if (sign * (s - head) <= 0.0) return k;
  if (sign * (s - tail) >= 0.0) return {k.density * std::pow(pk, 1.0 / g), u, p};
  // inside the fan, Toro eqs. 4.56 / 4.63
  const double factor = 2.0 / (g + 1.0) + sign * (g - 1.0) / ((g + 1.0) * c) * (k.velocity - s);
  const double density = k.density * std::pow(factor, 2.0 / (g - 1.0));
  const double velocity = 2.0 / (g + 1.0) * (sign * c + 0.5 * (g - 1.0) * k.velocity + s);
  return {density, velocity, k.pressure * std::pow(factor, 2.0 * g / (g - 1.0))};
}

std::vector<GasState> cell_averages(const ExactRiemannSolution& solution, double gamma,
                                    double x_lower, double x_upper, int cells, double x0, double t,
                                    int samples) {
  std::vector<GasState> averages(static_cast<std::size_t>(cells));
  const double dx = (x_upper - x_lower) / cells;
  for (int i = 0; i < cells; ++i) {
    double mass = 0.0, momentum = 0.0, energy = 0.0;
    for (int k = 0; k < samples; ++k) {
      const double x = x_lower + (i + (k + 0.5) / samples) * dx;
      const GasState s = solution.sample((x - x0) / t);
      mass += s.density;
      momentum += s.density * s.velocity;
      energy += s.pressure / (gamma - 1.0) + 0.5 * s.density * s.velocity * s.velocity;
    }
    mass /= samples;
    momentum /= samples;
    energy /= samples;
    const double u = momentum / mass;
    averages[static_cast<std::size_t>(i)] = {mass, u,
                                             (gamma - 1.0) * (energy - 0.5 * mass * u * u)};
  }
  return averages;
}

}  // namespace cosim::bench

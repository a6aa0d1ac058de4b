#pragma once

#include <cmath>
#include <stdexcept>

// Exact solution of the shallow-water Riemann problem of a dam break on a
// flat frictionless bed, still water on both sides (Toro, Shock-capturing
// methods for free-surface shallow flows, 2001, Ch. 5): depth h_l for
// x < x0, h_r (>= 0) beyond.
namespace cosim::bench {

class ExactDamBreak {
 public:
  ExactDamBreak(double h_l, double h_r, double x0, double g)
      : h_l_(h_l), h_r_(h_r), x0_(x0), g_(g) {
    c_l_ = std::sqrt(g * h_l);
    if (h_r <= 0.0) {  // Ritter: a rarefaction down to the dry bed
      h_star_ = 0.0;
      u_star_ = 2.0 * c_l_;
      shock_speed_ = 2.0 * c_l_;
      return;
    }
    // Newton on f_l(h) + f_r(h) = 0 (u_l = u_r = 0): left rarefaction,
    // right shock.
    double h = 0.5 * (h_l + h_r);
    for (int it = 0; it < 100; ++it) {
      const double f = rarefaction(h) + shock(h), df = rarefaction_slope(h) + shock_slope(h);
      const double next = h - f / df;
      if (std::abs(next - h) < 1e-15 * h_l) {
        h = next;
        break;
      }
      h = next;
    }
    h_star_ = h;
    u_star_ = 0.5 * (shock(h) - rarefaction(h));
    shock_speed_ = std::sqrt(g * h_r) * std::sqrt(0.5 * (h + h_r) * h / (h_r * h_r));
  }

  double depth(double x, double t) const {
    const double xi = (x - x0_) / t;
    if (xi <= -c_l_) return h_l_;
    if (xi < u_star_ - std::sqrt(g_ * h_star_)) {
      const double s = 2.0 * c_l_ - xi;
      return s * s / (9.0 * g_);
    }
    if (xi < shock_speed_) return h_star_;
    return h_r_;
  }

  double middle_depth() const { return h_star_; }
  double middle_velocity() const { return u_star_; }
  // Shock speed (C_s of Zheng et al., Sec. 4.2); the wet-front speed 2 c_l on a dry bed.
  double front_speed() const { return shock_speed_; }
  double rarefaction_head_speed() const { return -c_l_; }

 private:
  double rarefaction(double h) const { return 2.0 * (std::sqrt(g_ * h) - c_l_); }
  double rarefaction_slope(double h) const { return std::sqrt(g_ / h); }
  double shock(double h) const { return (h - h_r_) * shock_factor(h); }
  double shock_slope(double h) const {
    const double s = shock_factor(h);
    return s - (h - h_r_) * g_ / (4.0 * s * h * h);
  }
  double shock_factor(double h) const { return std::sqrt(0.5 * g_ * (h + h_r_) / (h * h_r_)); }

  double h_l_, h_r_, x0_, g_, c_l_;
  double h_star_ = 0.0, u_star_ = 0.0, shock_speed_ = 0.0;
};

}  // namespace cosim::bench

#pragma once

#include <vector>

// The exact solution of the Riemann problem of the 1D Euler equations for an
// ideal gas (Toro, Riemann Solvers and Numerical Methods for Fluid
// Dynamics, 3rd ed., ch. 4): the reference of Sod's shock tube.
namespace cosim::bench {

struct GasState {
  double density = 0.0;
  double velocity = 0.0;
  double pressure = 0.0;
};

class ExactRiemannSolution {
 public:
  // Throws std::invalid_argument for non-positive densities or pressures,
  // gamma <= 1, or states that would create a vacuum.
  ExactRiemannSolution(GasState left, GasState right, double gamma);

  double star_pressure() const { return star_pressure_; }
  double star_velocity() const { return star_velocity_; }
  // The state at x / t (the diaphragm at x = 0).
  GasState sample(double x_over_t) const;

 private:
  // f_K(p) of Toro eq. 4.6/4.7 and its derivative.
  double pressure_function(double p, const GasState& state, double sound_speed,
                           double& derivative) const;

  GasState left_, right_;
  double gamma_;
  double sound_left_, sound_right_;
  double star_pressure_ = 0.0;
  double star_velocity_ = 0.0;
};

// Cell averages of the solution at time t > 0 on `cells` uniform cells of
// [x_lower, x_upper] with the diaphragm at x0, each the mean of `samples`
// midpoint samples of density, momentum and total energy per unit volume,
// returned as primitive (rho, u = m / rho, p from the mean energy).
std::vector<GasState> cell_averages(const ExactRiemannSolution& solution, double gamma,
                                    double x_lower, double x_upper, int cells, double x0, double t,
                                    int samples = 64);

}  // namespace cosim::bench

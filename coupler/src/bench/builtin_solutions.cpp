#include "builtin_solutions.hpp"

#include <algorithm>
#include <cmath>

#include "bench/darcy_column.hpp"
#include "bench/gas_riemann_problem.hpp"
#include "bench/shallow_water_dam_break.hpp"
#include "bench/terzaghi_consolidation.hpp"

namespace cosim::bench {

namespace {

// Tran et al., MPMICE, eq. 98.
class DarcyPoreVelocity final : public AnalyticSolution {
 public:
  std::string name() const override { return "darcy_pore_velocity"; }
  std::string doc() const override {
    return "Steady pore-water velocity through a column of grains (Tran et al., MPMICE, eq. 98): "
           "U_f = (1/n) d^2 (1 - phi_s)^3 / (180 phi_s^2 mu) dp / L [m/s].";
  }
  std::vector<ParameterDoc> parameters() const override {
    return {{"solid_fraction", "phi_s = 1 - n", std::nullopt},
            {"pressure_drop", "dp across the column [Pa]", std::nullopt},
            {"grain_size", "d [m]", std::nullopt},
            {"viscosity", "mu [Pa s]", 1.0e-3},
            {"length", "L, the column's length [m]", std::nullopt}};
  }
  bool is_curve() const override { return false; }
  double value(const Parameters& p, double, double) const override {
    return DarcyColumn{p.at("grain_size"), p.at("viscosity"), p.at("length")}.pore_velocity(
        p.at("solid_fraction"), p.at("pressure_drop"));
  }

 protected:
  std::string check_values(const Parameters& p) const override {
    const double phi = p.at("solid_fraction");
    if (!(phi > 0.0 && phi < 1.0)) return "solid_fraction must be in (0, 1)";
    if (!(p.at("grain_size") > 0.0 && p.at("viscosity") > 0.0 && p.at("length") > 0.0))
      return "grain_size, viscosity and length must be positive";
    return {};
  }
};

// Pan et al. 2021, eq. 82; Tran et al., MPMICE, eq. 99.
class TerzaghiExcessPressure final : public AnalyticSolution {
 public:
  std::string name() const override { return "terzaghi_excess_pressure"; }
  std::string doc() const override {
    return "Excess pore pressure of a column drained at the top under a load p0 (Pan et al. "
           "2021, eq. 82; Tran et al., MPMICE, eq. 99) against the height above the column's "
           "impermeable bottom [Pa]; c_v given, or k E_oed / mu with the Kozeny-Carman "
           "permeability k = d^2 n^3 / (C (1 - n)^2).";
  }
  std::vector<ParameterDoc> parameters() const override {
    return {{"height", "h, the column's height [m]", std::nullopt},
            {"load", "p0 [Pa]", std::nullopt},
            {"bottom", "height of the column's bottom [m]", 0.0},
            {"consolidation_coefficient", "c_v [m^2/s]; 0: from the skeleton and grains", 0.0},
            {"youngs_modulus", "E of the skeleton [Pa]", 0.0},
            {"poisson_ratio", "nu of the skeleton", 0.0},
            {"grain_size", "d [m]", 0.0},
            {"porosity", "n", 0.0},
            {"viscosity", "mu [Pa s]", 1.0e-3},
            {"kozeny_constant", "C: 180 (Tran et al.) or 150 (Pan et al., eq. 4)", 180.0},
            {"ramp_time", "the load rises over it [s]; 0: at once", 0.0},
            {"cycloidal_ramp", "1: the ramp is cycloidal, 0: linear", 0.0}};
  }
  bool is_curve() const override { return true; }
  double value(const Parameters& p, double z, double t) const override {
    return column(p).excess_pressure(z - p.at("bottom"), t);
  }

 protected:
  std::string check_values(const Parameters& p) const override {
    if (!(p.at("height") > 0.0)) return "height must be positive";
    if (!(column(p).consolidation > 0.0))
      return "give consolidation_coefficient > 0, or youngs_modulus, poisson_ratio, grain_size, "
             "porosity and viscosity";
    return {};
  }

 private:
  static TerzaghiColumn column(const Parameters& p) {
    TerzaghiColumn c;
    c.height = p.at("height");
    c.load = p.at("load");
    c.ramp_time = p.at("ramp_time");
    c.cycloidal_ramp = p.at("cycloidal_ramp") != 0.0;
    c.consolidation = p.at("consolidation_coefficient");
    if (c.consolidation <= 0.0) {
      const double n = p.at("porosity"), d = p.at("grain_size");
      const double k = d * d * n * n * n / (p.at("kozeny_constant") * (1.0 - n) * (1.0 - n));
      c.consolidation =
          k * oedometric_modulus(p.at("youngs_modulus"), p.at("poisson_ratio")) / p.at("viscosity");
    }
    return c;
  }
};

// Stoker (wet bed) or Ritter (dry bed), Toro 2001, ch. 5; Zheng et al., Sec. 4.2.
class DamBreakDepth final : public AnalyticSolution {
 public:
  std::string name() const override { return "dam_break_depth"; }
  std::string doc() const override {
    return "Water depth of a dam break on a flat frictionless bed against x: Stoker's solution "
           "on a wet bed, Ritter's on a dry one (Zheng et al., Sec. 4.2) [m].";
  }
  std::vector<ParameterDoc> parameters() const override {
    return {{"left_depth", "h_l [m]", std::nullopt},
            {"right_depth", "h_r [m] (0: dry)", std::nullopt},
            {"dam_position", "x0 [m]", std::nullopt},
            {"gravity", "g [m/s^2]", 9.81}};
  }
  bool is_curve() const override { return true; }
  double value(const Parameters& p, double x, double t) const override {
    if (t <= 0.0) return x < p.at("dam_position") ? p.at("left_depth") : p.at("right_depth");
    return ExactDamBreak(p.at("left_depth"), p.at("right_depth"), p.at("dam_position"),
                         p.at("gravity"))
        .depth(x, t);
  }

 protected:
  std::string check_values(const Parameters& p) const override {
    if (!(p.at("left_depth") > p.at("right_depth") && p.at("right_depth") >= 0.0))
      return "left_depth must exceed right_depth >= 0";
    return {};
  }
};

// Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, ch. 4.
class ShockTube final : public AnalyticSolution {
 public:
  enum class Variable { density, pressure, velocity };
  explicit ShockTube(Variable v) : variable_(v) {}
  std::string name() const override {
    switch (variable_) {
      case Variable::density:
        return "shock_tube_density";
      case Variable::pressure:
        return "shock_tube_pressure";
      case Variable::velocity:
        return "shock_tube_velocity";
    }
    return {};
  }
  std::string doc() const override {
    return "Exact Riemann solution of the Euler equations of an ideal gas (Sod's shock tube; "
           "Toro, ch. 4) against x.";
  }
  std::vector<ParameterDoc> parameters() const override {
    return {{"left_density", "[kg/m^3]", std::nullopt},
            {"left_pressure", "[Pa]", std::nullopt},
            {"left_velocity", "[m/s]", 0.0},
            {"right_density", "[kg/m^3]", std::nullopt},
            {"right_pressure", "[Pa]", std::nullopt},
            {"right_velocity", "[m/s]", 0.0},
            {"gamma", "ratio of specific heats", 1.4},
            {"diaphragm", "x0 [m]", std::nullopt}};
  }
  bool is_curve() const override { return true; }
  double value(const Parameters& p, double x, double t) const override {
    const ExactRiemannSolution s(
        {p.at("left_density"), p.at("left_velocity"), p.at("left_pressure")},
        {p.at("right_density"), p.at("right_velocity"), p.at("right_pressure")}, p.at("gamma"));
    const double dx = x - p.at("diaphragm");
    const GasState state = t > 0.0 ? s.sample(dx / t) : s.sample(dx < 0.0 ? -1e300 : 1e300);
    switch (variable_) {
      case Variable::density:
        return state.density;
      case Variable::pressure:
        return state.pressure;
      case Variable::velocity:
        return state.velocity;
    }
    return 0.0;
  }

 protected:
  std::string check_values(const Parameters& p) const override {
    if (!(p.at("left_density") > 0.0 && p.at("right_density") > 0.0 &&
          p.at("left_pressure") > 0.0 && p.at("right_pressure") > 0.0 && p.at("gamma") > 1.0))
      return "densities and pressures must be positive and gamma > 1";
    return {};
  }

 private:
  Variable variable_;
};

class HydrostaticPressure final : public AnalyticSolution {
 public:
  std::string name() const override { return "hydrostatic_pressure"; }
  std::string doc() const override {
    return "Pressure of still water against height y: p_s + rho g (surface - y) below the "
           "surface, p_s above [Pa].";
  }
  std::vector<ParameterDoc> parameters() const override {
    return {{"surface", "height of the free surface [m]", std::nullopt},
            {"density", "rho [kg/m^3]", std::nullopt},
            {"gravity", "g [m/s^2]", 9.81},
            {"surface_pressure", "p_s [Pa]", 0.0}};
  }
  bool is_curve() const override { return true; }
  double value(const Parameters& p, double y, double) const override {
    return p.at("surface_pressure") +
           p.at("density") * p.at("gravity") * std::max(p.at("surface") - y, 0.0);
  }
};

}  // namespace

std::vector<std::unique_ptr<AnalyticSolution>> builtin_solutions() {
  std::vector<std::unique_ptr<AnalyticSolution>> all;
  all.push_back(std::make_unique<DarcyPoreVelocity>());
  all.push_back(std::make_unique<TerzaghiExcessPressure>());
  all.push_back(std::make_unique<DamBreakDepth>());
  all.push_back(std::make_unique<ShockTube>(ShockTube::Variable::density));
  all.push_back(std::make_unique<ShockTube>(ShockTube::Variable::pressure));
  all.push_back(std::make_unique<ShockTube>(ShockTube::Variable::velocity));
  all.push_back(std::make_unique<HydrostaticPressure>());
  return all;
}

}  // namespace cosim::bench

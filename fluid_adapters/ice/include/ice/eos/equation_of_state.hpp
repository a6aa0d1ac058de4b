#pragma once

#include <cmath>
#include <string_view>

namespace ice {

// The thermodynamic state of one fluid material, [P_f, rho_f, T_f, e_f]
// (Tran et al., MPMICE, eq. 10): pressure from intrinsic density and
// temperature, its inverse, and the derivatives the pressure equilibration
// (eqs. 42-43) and the implicit pressure solve (eq. 52) need. Densities are
// intrinsic (micro) densities rho_f = M_f / V_f, not bulk densities. SI units;
// temperatures in kelvin. Models are immutable once built.
class EquationOfState {
 public:
  virtual ~EquationOfState() = default;

  // The registry name of the model ("ideal_gas").
  virtual std::string_view type() const = 0;

  // P_f(rho_f, T_f) [Pa].
  virtual double pressure(double density, double temperature) const = 0;
  // rho_f(P_f, T_f) [kg/m3], the inverse of pressure() at fixed T_f; positive
  // only for pressure > minimum_pressure(temperature).
  virtual double density(double pressure, double temperature) const = 0;
  // The pressure at which the density reaches zero: no state exists at or
  // below it (0 for an ideal gas) [Pa].
  virtual double minimum_pressure(double temperature) const = 0;

  // (dP/drho)_T [m2/s2], the squared isothermal sound speed.
  virtual double dpressure_ddensity(double density, double temperature) const = 0;
  // alpha_f = (1/V_f)(dV_f/dT)_P = -(1/rho)(drho/dT)_P [1/K] (MPMICE, eq. 103,
  // per unit volume of the fluid itself).
  virtual double thermal_expansivity(double density, double temperature) const = 0;

  // Isothermal compressibility kappa_f = -(1/V_f)(dV_f/dP)_T = 1 / (rho_f c_T^2)
  // [1/Pa], per unit volume of the fluid itself. MPMICE eq. 102 writes it per
  // cell volume V, which is phi_f times this; the mixture compressibility of
  // eq. 52, kappa = sum phi_f kappa_f / sum phi_f, takes this intrinsic one.
  double compressibility(double density, double temperature) const {
    return 1.0 / (density * dpressure_ddensity(density, temperature));
  }
  // c_T = sqrt((dP/drho)_T) [m/s].
  double isothermal_sound_speed(double density, double temperature) const {
    return std::sqrt(dpressure_ddensity(density, temperature));
  }

  // The adiabatic (isentropic) sound speed squared [m2/s2],
  //   c_s^2 = (dP/drho)_s = c_T^2 + T (dP/dT)_rho^2 / (rho^2 c_v),
  // with (dP/dT)_rho = rho alpha c_T^2: for an ideal gas gamma R T. The
  // implicit pressure step takes the adiabatic compressibility, so that a
  // compression heats the fluid through -P dV (eq. 60) as the EOS expects.
  double adiabatic_sound_speed_squared(double density, double temperature) const {
    const double c_t2 = dpressure_ddensity(density, temperature);
    const double alpha = thermal_expansivity(density, temperature);
    return c_t2 + temperature * c_t2 * c_t2 * alpha * alpha / specific_heat_;
  }
  // kappa_s = 1 / (rho c_s^2) [1/Pa].
  double adiabatic_compressibility(double density, double temperature) const {
    return 1.0 / (density * adiabatic_sound_speed_squared(density, temperature));
  }

  // c_v [J/(kg K)] and e_f = c_v T_f [J/kg] (MPMICE, eqs. 63, 73).
  double specific_heat() const { return specific_heat_; }
  double specific_internal_energy(double temperature) const { return specific_heat_ * temperature; }

 protected:
  explicit EquationOfState(double specific_heat) : specific_heat_(specific_heat) {}

 private:
  double specific_heat_;
};

}  // namespace ice

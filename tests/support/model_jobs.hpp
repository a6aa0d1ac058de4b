#pragma once

#include <filesystem>
#include <string>

// Model problems of the coupler's tests, on test participants
// (cosim_test_participant), written as a job and its participants' configs
// into a directory.
namespace cosim::testing {

// A fixed point across the interface: `left` writes a = 1 + a_gain b and
// `right` writes b = 2 + b_gain a per cell (4 cells, windows of 0.01 s to
// 0.1 s). With the default gains the fixed point is a = 0.8, b = -0.4, and
// explicit coupling's Jacobi iteration over windows diverges
// (|0.5 * 3| > 1). `coupling` is the job's coupling block (YAML).
void write_fixed_point_case(const std::filesystem::path& dir, const std::string& coupling,
                            double a_gain = 0.5, double b_gain = -3.0,
                            const std::string& b_args = "[]");

// A fluid (rho_bar_f = 600 kg/m^3, pushed by f = 6000 N/m^3) dragging a
// porous solid (rho_bar_s = 1590 kg/m^3) through a constant K whose
// relaxation time tau = 1 / (K (1/rho_f + 1/rho_s)) = 1e-6 s is 1e-4 of the
// 0.01 s window, to 0.1 s; participants `water` and `soil`, the exchange by
// the coupler's momentum_exchange.
inline constexpr double model_window = 1.0e-2, model_rho_f = 600.0, model_rho_s = 1590.0;
inline constexpr double model_force = 6000.0, model_tau = 1.0e-6;
inline const double model_drag = 1.0 / (model_tau * (1.0 / model_rho_f + 1.0 / model_rho_s));
void write_stiff_drag_case(const std::filesystem::path& dir, const std::string& coupling);

// The energy exchange's counterpart: a heated fluid (C_f = 1.67e6 J/(m^3 K),
// S = 1e6 W/m^3) and a solid (C_s = 1.25e6 J/(m^3 K)), both at 300 K at
// first, exchanging heat at a coefficient H whose relaxation time
// tau = 1 / (H (1/C_f + 1/C_s)) = 1e-6 s is 1e-4 of the 0.01 s window, to
// 0.1 s; participants `water` and `rock`, the exchange by the coupler's
// energy_exchange.
inline constexpr double heat_c_f = 1.67e6, heat_c_s = 1.25e6, heat_source = 1.0e6;
inline constexpr double heat_t0 = 300.0, heat_tau = 1.0e-6, heat_window = 1.0e-2;
void write_stiff_heat_case(const std::filesystem::path& dir, const std::string& coupling);

// The convergence measures of the Terzaghi column's implicit jobs
// (configs/ice_coupled/terzaghi), a `convergence:` list in a coupling block:
// relative limits, with absolute floors on the solid's velocity and the pore
// pressure's force, which start from zero (a relative limit on a field at
// round-off never holds).
inline constexpr const char* terzaghi_convergence = R"(  convergence:
    - {field: water.solid_fraction, relative: 1.0e-5}
    - {field: water.solid_velocity, relative: 1.0e-5, absolute: 1.0e-9}
    - {field: soil.pore_pressure, relative: 1.0e-5}
    - {field: soil.pore_pressure_force, relative: 1.0e-5, absolute: 1.0e-5}
)";

}  // namespace cosim::testing

#pragma once

#include <span>

// Implicit exchange between N materials sharing a cell (Tran et al., MPMICE,
// eqs. 23, 131 and the N-material form after eq. 132). For each material i
// it solves, for the increments Delta x_i of an intensive quantity x,
//
//   w_i Delta x_i = dt sum_j C_ij (x*_j + Delta x_j - x*_i - Delta x_i),
//
// i.e. (W + dt L) Delta x = -dt L x* with L the graph Laplacian of C. For
// momentum w = bulk density rho_bar [kg m^-3], x = velocity [m s^-1] and
// C = drag coefficient K [kg m^-3 s^-1]; for energy w = rho_bar c_v
// [J m^-3 K^-1], x = temperature [K] and C = H [W m^-3 K^-1].
// The solve is backward Euler in the exchange term: unconditionally stable
// for any C >= 0, and sum_i w_i Delta x_i = 0 to round-off.
//
// Weights select how a material takes part:
//   w_i > 0 finite  an ordinary material;
//   w_i = 0         absent from the cell: Delta x_i = 0, it couples to nothing;
//   w_i = +inf      held (infinite inertia, e.g. a fixed support): Delta x_i = 0,
//                   the others exchange with it; sum_i w_i Delta x_i is then the
//                   impulse the support absorbs and is not zero.
namespace cosim::exchange {

inline constexpr int kMaxMaterials = 8;
inline constexpr int kMaxComponents = 3;

// The exchange in closed form for two materials: the impulse density
// [w x] given to material 1 (material 2 receives its negative),
//   J_1 = (x*_2 - x*_1) / (1 / (dt C) + 1 / w_1 + 1 / w_2),
// so that the relative value x_1 - x_2 decays as
//   (x*_1 - x*_2) / (1 + dt C (1/w_1 + 1/w_2))   (Tran et al., eq. 131).
// Finite for C = +inf or w = +inf; zero when C = 0 or either w = 0.
double two_material_impulse(double weight_1, double weight_2, double value_1, double value_2,
                            double dt_coefficient);

// The general solver. `value` and `increment` are material-major
// (value[i * components + c]); `coefficient` is N x N row-major, only its
// upper triangle (i < j) is read, every entry finite and >= 0. N = weight.size()
// <= kMaxMaterials, 1 <= components <= kMaxComponents. Two present materials
// use the closed form. More are solved as pairwise impulses
// G_ij (x*_j - x*_i) with the effective conductances G = W (W + dt L)^-1 W,
// computed by an elimination that never subtracts (accurate for coefficients
// spread over many decades, where LDLT is not); pairwise antisymmetry makes
// sum_i w_i Delta x_i vanish up to the rounding of the sums.
void solve_implicit_exchange(std::span<const double> weight, std::span<const double> value,
                             int components, std::span<const double> coefficient, double dt,
                             std::span<double> increment);

// The same exchange returning the new values x*_i + Delta x_i, solved for
// directly: (W + dt L_uu) x_u = W x*_u + dt sum_h C_uh x*_h over the unknowns u
// (held and absent materials keep x*). For data x* >= 0 the right-hand side is
// non-negative and the subtraction-free elimination gives every new value to
// a few ulps of its own size, however small; x* + Delta x from
// solve_implicit_exchange cancels to zero or below where a material with
// little weight is tied to a held one (w_i << dt C_ih: x_i -> x_h w_i /
// (w_i + dt C_ih)). Use it for coefficients that must stay positive (the face
// coefficients of ICE's pressure correction); it does not have the pairwise
// form that makes sum_i w_i Delta x_i vanish to round-off.
void solve_implicit_exchange_values(std::span<const double> weight, std::span<const double> value,
                                    int components, std::span<const double> coefficient, double dt,
                                    std::span<double> new_value);

// Momentum: bulk densities rho_bar_i [kg m^-3], velocities U*_i [m s^-1]
// (dim per material), drag coefficients K_ij [kg m^-3 s^-1]; gives Delta U_i.
void exchange_momentum(std::span<const double> bulk_density, std::span<const double> velocity,
                       int dim, std::span<const double> drag, double dt,
                       std::span<double> velocity_increment);

// Energy (Tran et al., eq. 23 with eta_ij = dt H_ij / (rho_bar_i c_v,i)):
// bulk densities [kg m^-3], specific heats c_v [J kg^-1 K^-1], temperatures
// [K], heat exchange coefficients H_ij [W m^-3 K^-1]; gives Delta T_i and
// keeps sum_i rho_bar_i c_v,i T_i.
void exchange_energy(std::span<const double> bulk_density, std::span<const double> specific_heat,
                     std::span<const double> temperature, std::span<const double> heat_exchange,
                     double dt, std::span<double> temperature_increment);

}  // namespace cosim::exchange

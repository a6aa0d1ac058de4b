#pragma once

// The drag of MPPICInterFoam's parcels in OpenFOAM v1912 (ErgunWenYuDrag of
// the kinematic cloud): Ergun's packed-bed law below a fluid fraction of 0.8,
// Wen and Yu's above. Per unit cell volume the cloud pulls the fluid with
//   f = K_cloud (U_s - U_f),
//   K_cloud = phi_s (150 phi_s / n + 1.75 Re) mu / (n d^2)                n < 0.8
//   K_cloud = phi_s 0.75 CdRe(n Re) mu n^-2.65 / (n d^2)                  n >= 0.8
// with n = alphac (clipped below at 1 - alphaMax), Re = rho |U_f - U_s| d / mu
// and CdRe(Re) = 24 (1 + 0.15 Re^0.687) (0.44 Re above Re = 1000), the solid
// receiving -f.
//
// MPPICInterFoam's water takes the whole pressure gradient (-grad p, not
// -n grad p), so at steady state its drag balances grad p itself: the cloud
// coefficient that gives the Darcy flux of a mixture-theory law K (Tran et
// al., MPMICE, eq. 24: n grad p = K (U_s - U_f)) is K_cloud = K / n.
namespace openfoam {

struct CloudDragInput {
  double solid_fraction = 0.0;  // phi_s = 1 - n
  double fluid_density = 0.0;   // rho of the water-air mixture in the cell [kg/m^3]
  double viscosity = 0.0;       // mu of the mixture [Pa s]
  double relative_speed = 0.0;  // |U_f - U_s| [m/s]
};

// K_cloud [kg m^-3 s^-1] of parcels of diameter d [m].
double ergun_wen_yu_coefficient(const CloudDragInput& input, double grain_size);

// The parcels' diameters the adapter uses [m].
inline constexpr double smallest_grain = 1e-9;
inline constexpr double largest_grain = 10.0;

// The diameter for which the cloud's coefficient is `coefficient` at the
// input's relative speed (K_cloud falls strictly with d), found to a relative
// 1e-12. Throws cosim::NumericalError when no diameter in [smallest_grain,
// largest_grain] gives it.
double ergun_wen_yu_grain_size(const CloudDragInput& input, double coefficient);

// The same, clamped to that range: a coefficient weaker than the largest
// grain's (a trace of soil) gets the largest grain.
double ergun_wen_yu_grain_size_within_range(const CloudDragInput& input, double coefficient);

}  // namespace openfoam

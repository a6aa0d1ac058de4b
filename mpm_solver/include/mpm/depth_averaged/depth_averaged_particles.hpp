#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mpm/core/tensor.hpp"

namespace mpm {

// Material points in the plane of the ground, each a column of the moving
// mass: its volume is fixed and its plan area follows the flow's areal
// strain, so its depth V_p / A_p thins where the mass spreads (down to the
// thin tongue of a dam break's front, which a depth smoothed over the grid's
// cells could not resolve) and thickens where it converges.
struct DepthAveragedParticles {
  std::vector<Vec<2>> position;  // [m]
  std::vector<Vec<2>> velocity;  // depth-averaged [m/s]
  std::vector<double> volume;    // V_p [m^3]
  std::vector<double> area;      // A_p, plan area [m^2]
  // The point's two edge vectors [m] (columns): its lattice spacing at
  // seeding, deformed with the flow. A point stretched past the grid's
  // resolution is split in two along its longer edge.
  std::vector<Mat<2>> edges;
  std::vector<double> mass;               // [kg]
  std::vector<int> material;              // index into the solver's materials
  std::vector<double> areal_strain_rate;  // div u [1/s]
  std::vector<Mat<2>> velocity_gradient;  // L = grad u of the last step [1/s]
  std::vector<Mat<2>> stress;             // in-plane, beyond the earth pressure [Pa]
  std::vector<char> yielded;              // the in-plane stress yielded in the last step
  std::vector<double> damage;             // D = 1 - c / c0
  std::vector<double> structured_share;   // f_sc: solids still bound in structures
  std::vector<double> confined_fluid;     // fluid still confined in the structures [m^3]
  std::vector<double> released_fluid;     // fluid released since taken (eq. 27) [m^3]

  std::size_t size() const { return position.size(); }
  double depth(std::size_t p) const { return volume[p] / area[p]; }
  double density(std::size_t p) const { return mass[p] / volume[p]; }
  // A column of the given depth [m] over the plan area [m^2], with edges
  // (default: a square of that area).
  void add(const Vec<2>& x, const Vec<2>& v, double depth, double area, double density,
           int material, const Mat<2>& edges = Mat<2>::Zero());
  // Halves point p along its edge `edge` (0 or 1): the two halves sit a
  // quarter of that edge before and after its position, each with half the
  // volume, area and mass and the same velocity and state, so mass, momentum
  // and the centre of mass are kept exactly. Returns the new point's index.
  std::size_t split(std::size_t p, int edge);

  // Points at the Gauss-Legendre points of each seeding cell (`per_cell` of
  // 2 to 4 per direction) over the box [lower, upper] cut into cells of
  // `spacing`, each carrying the volume of the depth given at its position
  // times its quadrature weight (points where the depth is not positive are
  // left out). With the grid's cells, lower on a grid line, the grid then
  // integrates its quadratic shape functions exactly: a uniform layer has a
  // uniform depth up to the walls. Returns how many were added; throws
  // std::invalid_argument for another per_cell.
  std::size_t seed(const Vec<2>& lower, const Vec<2>& upper, const Vec<2>& spacing, int per_cell,
                   const std::function<double(const Vec<2>&)>& depth_at, double density,
                   int material, const Vec<2>& v = Vec<2>::Zero());

  double total_mass() const;
  Vec<2> momentum() const;
  Vec<2> centre_of_mass() const;
};

}  // namespace mpm

#pragma once

#include <span>

#include "ice/grid/grid_fields.hpp"

namespace ice {

struct PressureSolution {
  int iterations = 0;
  // ||b - A dP|| / ||b|| of the returned dP (0 for b = 0).
  double relative_residual = 0.0;
};

// A solver of the implicit pressure equation of the ICE step (Tran et al.,
// MPMICE, eq. 125; PressureSolver states the discrete system). The built-in
// PressureSolver solves it on one process; a distributed one (PETSc, issue
// 27) solves the rows of a block's own cells together with the other
// blocks and leaves dP in those cells only.
template <int Dim>
class PressureSystemSolver {
 public:
  virtual ~PressureSystemSolver() = default;

  // dP for the cell and face fields of the solver's grid: `kappa` the
  // mixture compressibility per cell, `face_density` rho_FC per face,
  // `predicted_velocity` U*_FC, `volume_source` a rate [1/s] at which pore
  // space opens per cell (or empty). `pressure_increment` holds the initial
  // guess on entry. Throws cosim::NumericalError when the solve does not
  // converge.
  virtual PressureSolution solve(std::span<const double> kappa, const FaceField<Dim>& face_density,
                                 const FaceField<Dim>& predicted_velocity, double dt,
                                 std::span<double> pressure_increment,
                                 std::span<const double> volume_source) = 0;
};

}  // namespace ice

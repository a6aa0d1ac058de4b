#pragma once

#include <cstddef>
#include <vector>

#include "solver_1d/line_cells.hpp"
#include "swe/physics.hpp"
#include "swe/scheme.hpp"
#include "swe/solver_1d.hpp"

namespace swe::solver_1d {

// Per-thread work arrays of one block of cells.
struct StageScratch {
  std::vector<double> storage;
};

// One stage of the SSP-RK2 step on the interior cells (arrays of n + 4
// values, ghosts filled):
//   out = base_weight * base + (1 - base_weight) * (in + dt L(in)),
// where L is the finite-volume residual of the flux and bed source
// (Zheng et al., eqs. 28-29). Depths left negative by round-off become 0 and
// dry cells (h < dry_depth) lose their momentum. `out` may alias `base`
// (never `in`).
struct StageArrays {
  const double* h_in;
  const double* q_in;
  const double* bed;
  const double* h_base;
  const double* q_base;
  double* h_out;
  double* q_out;
};

// Mass fluxes imposed on the two boundary faces (inflow_discharge), in the +x
// direction; the momentum flux there stays the Riemann solver's.
struct ImposedMassFlux {
  bool left = false, right = false;
  double left_value = 0.0, right_value = 0.0;
};

// The state (h, q) and the first stage's arrays, n + 4 values each (ghosts
// of h and q filled).
struct StepArrays {
  double* h;
  double* q;
  const double* bed;
  double* h_stage;
  double* q_stage;
};

// One SSP-RK2 (Heun) step of the interior cells, Zheng et al.'s eq. 28 as
// the stages of the optimal second-order TVD Runge-Kutta scheme (Gottlieb &
// Shu, Math. Comp. 67, 1998):
//   U1 = U + dt L(U),  U <- U/2 + (U1 + dt L(U1))/2,
// two stages as above, the ghosts of U1 filled from the boundaries between
// them (the ghosts of U are left for the caller). Each thread walks its
// blocks once, stage 2 one block behind stage 1, so the stage values are
// read back from cache.
void advance_step(const LineCells& cells, const Physics& physics, const Scheme& scheme,
                  const Boundaries1d& boundaries, const StepArrays& a,
                  const ImposedMassFlux& imposed, double dt, std::vector<StageScratch>& scratch);

}  // namespace swe::solver_1d

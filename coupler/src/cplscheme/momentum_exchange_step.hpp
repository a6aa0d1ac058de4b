#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "com/handshake.hpp"
#include "exchange/drag_law.hpp"
#include "explicit_stability.hpp"
#include "job/job.hpp"
#include "operator_cache.hpp"
#include "phase_side.hpp"

namespace cosim::cplscheme {

// The coupler's implicit momentum exchange of a fluid and a porous solid
// (architecture.md §4; Tran et al., MPMICE, eq. 131): the phases' fields are
// mapped consistently onto the exchange mesh, the 2x2 exchange is solved per
// cell with beta = window K / rho_bar, and the momentum each phase receives
// is mapped conservatively back to it. Momentum is conserved to round-off.
// With `solved_by: fluid` the step only evaluates K on the exchange mesh for
// the fluid (mapped consistently to its `drag_coefficient`) and hands the
// momentum the fluid gave the solid over the window (its written
// `momentum_exchange_impulse`) conservatively to the solid.
// Momentum per cell of the exchange mesh, dim per cell [kg m/s].
struct ExchangeCellImpulses {
  std::vector<double> fluid;
  std::vector<double> solid;
};

class MomentumExchangeStep {
 public:
  MomentumExchangeStep(const job::MomentumExchangeSpec& spec, const std::string& job_file);

  // Refuses declarations the exchange cannot use (components, quantity,
  // time treatment), as an InputError located at the job's key.
  void check_declarations(const job::Job& job, const com::Hello& fluid,
                          const com::Hello& solid) const;

  struct Impulses {
    std::vector<double> fluid;            // on the fluid's impulse mesh, dim per element [kg m/s]
    std::vector<double> solid;            // on the solid's impulse mesh
    double momentum_balance_error = 0.0;  // |sum fluid + sum solid| / sum |fluid|
    // solved_by fluid: K on the fluid's drag_coefficient mesh (`fluid` stays
    // empty), and the balance error compares what the solid receives with what
    // the fluid wrote.
    std::vector<double> drag_coefficient;
    // solved_by coupler: the momentum each phase receives per exchange cell,
    // before it is mapped to the phase.
    ExchangeCellImpulses on_exchange_mesh;
  };
  // `applied`: in an implicit scheme, the momentum the phases were given in
  // the window being repeated (on the exchange mesh, as returned for the
  // iterate they ran). The exchange then acts on the window's predicted
  // velocities, U* = U - j / (rho_bar V), as a fluid solver's Lagrangian
  // velocities before its exchange (Tran et al., MPMICE, eqs. 48 and 131):
  // the momentum it returns does not depend on the momentum already applied,
  // and the iteration's fixed point is the backward-Euler drag of the window.
  Impulses run(double window, const PhaseSide& fluid, const PhaseSide& solid,
               OperatorCache& operators, const ExchangeCellImpulses* applied = nullptr) const;

  // The explicit coupling's stability bound on the exchange mesh
  // (explicit_stability.hpp), when the fluid writes its pore fluid's bulk
  // modulus (a compressible fluid; an incompressible one has no such wave).
  std::optional<ExplicitStabilityBound> explicit_window_bound(const PhaseSide& fluid,
                                                              const PhaseSide& solid,
                                                              OperatorCache& operators) const;

  // The largest K the fluid is sent: the impermeable limit of Tran et al.,
  // MPMICE (K = 1e15 for a solid without pores), which keeps every value
  // finite where the law gives +infinity.
  static constexpr double impermeable_drag = 1.0e15;

 private:
  const job::MomentumExchangeSpec& spec_;
  std::string job_file_;
  std::unique_ptr<exchange::DragLaw> law_;
};

}  // namespace cosim::cplscheme

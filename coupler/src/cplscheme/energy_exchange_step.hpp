#pragma once

#include <string>
#include <vector>

#include "com/handshake.hpp"
#include "job/job.hpp"
#include "operator_cache.hpp"
#include "phase_side.hpp"

namespace cosim::cplscheme {

// The coupler's implicit energy exchange of a fluid and a solid (Tran et
// al., MPMICE, eq. 23; job::EnergyExchangeSpec): both phases' temperatures
// and heat capacities per unit volume are mapped consistently onto the
// exchange mesh, each cell exchanges
//   q V dt,  q = (T_s - T_f) / (1 / (dt H) + 1 / C_f + 1 / C_s),
// and the heat each phase receives is mapped conservatively back to it.
// Energy is conserved to round-off.
// Heat per cell of the exchange mesh [J].
struct ExchangeCellHeat {
  std::vector<double> fluid;
  std::vector<double> solid;
};

class EnergyExchangeStep {
 public:
  explicit EnergyExchangeStep(const job::EnergyExchangeSpec& spec, const std::string& job_file);

  // Refuses declarations the exchange cannot use, located at the job's key.
  void check_declarations(const job::Job& job, const com::Hello& fluid,
                          const com::Hello& solid) const;

  struct Heat {
    std::vector<double> fluid;          // on the fluid's heat mesh [J]
    std::vector<double> solid;          // on the solid's heat mesh [J]
    double energy_balance_error = 0.0;  // |sum fluid + sum solid| / sum |fluid|
    ExchangeCellHeat on_exchange_mesh;  // before it is mapped to the phases
  };
  // `applied`: in an implicit scheme, the heat the phases were given in the
  // window being repeated (on the exchange mesh). The exchange then acts on
  // the window's predicted temperatures, T* = T - Q / (C V), as the momentum
  // exchange on predicted velocities: the heat it returns does not depend on
  // the heat already applied, and the fixed point is the window's
  // backward-Euler exchange.
  Heat run(double window, const PhaseSide& fluid, const PhaseSide& solid, OperatorCache& operators,
           const ExchangeCellHeat* applied = nullptr) const;

 private:
  const job::EnergyExchangeSpec& spec_;
  std::string job_file_;
};

}  // namespace cosim::cplscheme

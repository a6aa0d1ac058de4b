#include "energy_exchange_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"
#include "cosim/exchange/implicit_exchange.hpp"
#include "cosim/fields.hpp"

namespace cosim::cplscheme {

namespace f = fields;

EnergyExchangeStep::EnergyExchangeStep(const job::EnergyExchangeSpec& spec,
                                       const std::string& job_file)
    : spec_(spec), job_file_(job_file) {}

void EnergyExchangeStep::check_declarations(const job::Job&, const com::Hello& fluid,
                                            const com::Hello& solid) const {
  auto fail = [&](const std::string& what) {
    throw InputError(SourceLocation{job_file_, spec_.where.line, spec_.where.column},
                     "energy_exchange", what);
  };
  auto check = [&](const com::Hello& hello, const std::vector<FieldSpec>& declared,
                   const fields::Field& needed) {
    auto it = std::find_if(declared.begin(), declared.end(),
                           [&](auto& x) { return x.name == needed.name; });
    if (it == declared.end())
      fail(fmt::format("participant '{}' does not declare '{}'", hello.participant, needed.name));
    if (it->components != 1 || it->quantity != needed.quantity || it->time != needed.time)
      fail(fmt::format(
          "participant '{}' declares '{}' as {} {} with {} components; the exchange needs {} {} "
          "with 1",
          hello.participant, needed.name, to_string(it->quantity), to_string(it->time),
          it->components, to_string(needed.quantity), to_string(needed.time)));
  };
  check(solid, solid.writes, f::solid_temperature);
  check(solid, solid.writes, f::solid_heat_capacity);
  check(fluid, fluid.writes, f::fluid_temperature);
  check(fluid, fluid.writes, f::fluid_heat_capacity);
  for (const com::Hello* side : {&fluid, &solid})
    check(*side, side->reads, f::heat_exchange_energy);
}

EnergyExchangeStep::Heat EnergyExchangeStep::run(double window, const PhaseSide& fluid,
                                                 const PhaseSide& solid, OperatorCache& operators,
                                                 const ExchangeCellHeat* applied) const {
  const PhaseSide& owner = spec_.mesh_owner == spec_.fluid ? fluid : solid;
  const Mesh& exchange_mesh = owner.mesh(spec_.mesh);
  const std::size_t exchange_version = owner.version(spec_.mesh);
  const MeshName exchange_name{spec_.mesh_owner, spec_.mesh};
  const std::size_t cells = exchange_mesh.size();
  auto on_exchange_mesh = [&](const PhaseSide& side, const char* field) {
    const std::string& mesh = side.spec->writes.at(field);
    const OperatorKey key{{side.spec->name, mesh},
                          exchange_name,
                          mapping::Constraint::consistent,
                          mapping::Kernel::linear};
    return operators.get(key, side.mesh(mesh), side.version(mesh), exchange_mesh, exchange_version)
        .apply(side.written->at(field), 1);
  };
  auto t_f = on_exchange_mesh(fluid, f::fluid_temperature.name);
  const auto c_f = on_exchange_mesh(fluid, f::fluid_heat_capacity.name);
  auto t_s = on_exchange_mesh(solid, f::solid_temperature.name);
  const auto c_s = on_exchange_mesh(solid, f::solid_heat_capacity.name);
  std::vector<double> q_f(cells), q_s(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    const auto bad = [&](const char* what, double value) {
      throw NumericalError(fmt::format("energy exchange: cell {} of {}.{} has {} {}", c,
                                       spec_.mesh_owner, spec_.mesh, what, value));
    };
    if (!(c_f[c] >= 0.0) || !std::isfinite(c_f[c])) bad("fluid heat capacity", c_f[c]);
    if (!(c_s[c] >= 0.0) || !std::isfinite(c_s[c])) bad("solid heat capacity", c_s[c]);
    const bool present = c_f[c] > 0.0 && c_s[c] > 0.0;
    if (present && (!(t_f[c] > 0.0) || !std::isfinite(t_f[c]))) bad("fluid temperature", t_f[c]);
    if (present && (!(t_s[c] > 0.0) || !std::isfinite(t_s[c]))) bad("solid temperature", t_s[c]);
    if (present && applied && applied->fluid.size() == cells) {
      const double volume = exchange_mesh.control_volume(c);
      t_f[c] -= applied->fluid[c] / (c_f[c] * volume);
      t_s[c] -= applied->solid[c] / (c_s[c] * volume);
    }
    // Tran et al., MPMICE, eq. 23 in closed form: the heat per unit volume
    // the fluid receives; zero where either phase is absent.
    const double q = present ? exchange::two_material_impulse(c_f[c], c_s[c], t_f[c], t_s[c],
                                                              window * spec_.coefficient)
                             : 0.0;
    q_f[c] = q * exchange_mesh.control_volume(c);
    q_s[c] = -q_f[c];
  }
  auto to_side = [&](const PhaseSide& side, const std::vector<double>& heat) {
    const std::string& mesh = side.spec->reads.at(f::heat_exchange_energy.name);
    const OperatorKey key{exchange_name,
                          {side.spec->name, mesh},
                          mapping::Constraint::conservative,
                          mapping::Kernel::linear};
    return operators.get(key, exchange_mesh, exchange_version, side.mesh(mesh), side.version(mesh))
        .apply(heat, 1);
  };
  Heat out;
  out.fluid = to_side(fluid, q_f);
  out.solid = to_side(solid, q_s);
  out.on_exchange_mesh = {std::move(q_f), std::move(q_s)};
  double net = 0.0, scale = 0.0;
  for (double q : out.fluid) {
    net += q;
    scale += std::abs(q);
  }
  for (double q : out.solid) net += q;
  out.energy_balance_error = scale > 0.0 ? std::abs(net) / scale : 0.0;
  return out;
}

}  // namespace cosim::cplscheme

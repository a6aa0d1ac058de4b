#include "momentum_exchange_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"
#include "cosim/exchange/two_phase_exchange.hpp"

namespace cosim::cplscheme {

namespace f = job::momentum_exchange_fields;

namespace {

const FieldSpec* find(const std::vector<FieldSpec>& fields, const std::string& name) {
  auto it = std::find_if(fields.begin(), fields.end(), [&](auto& x) { return x.name == name; });
  return it == fields.end() ? nullptr : &*it;
}

}  // namespace

MomentumExchangeStep::MomentumExchangeStep(const job::MomentumExchangeSpec& spec,
                                           const std::string& job_file)
    : spec_(spec),
      job_file_(job_file),
      law_(exchange::make_drag_law(spec.drag, spec.drag_key_path, job_file)) {}

void MomentumExchangeStep::check_declarations(const job::Job& job, const com::Hello& fluid,
                                              const com::Hello& solid) const {
  const int dim = job.participant(spec_.mesh_owner)->meshes.at(spec_.mesh).dim;
  auto fail = [&](const std::string& what) {
    throw InputError(SourceLocation{job_file_, spec_.where.line, spec_.where.column},
                     "momentum_exchange", what);
  };
  auto check = [&](const com::Hello& hello, const std::vector<FieldSpec>& fields, const char* name,
                   int components, Quantity quantity, TimeTreatment time) {
    const FieldSpec* field = find(fields, name);
    if (!field)
      fail(fmt::format("participant '{}' does not declare '{}'", hello.participant, name));
    if (field->components != components || field->quantity != quantity || field->time != time)
      fail(
          fmt::format("participant '{}' declares '{}' as {} {} with {} components; the exchange "
                      "needs {} {} with {}",
                      hello.participant, name, to_string(field->quantity), to_string(field->time),
                      field->components, to_string(quantity), to_string(time), components));
  };
  const auto intensive = Quantity::intensive;
  const auto state = TimeTreatment::state;
  check(solid, solid.writes, f::solid_fraction, 1, intensive, state);
  check(solid, solid.writes, f::solid_velocity, dim, intensive, state);
  check(solid, solid.writes, f::solid_bulk_density, 1, intensive, state);
  if (law_->cell_input() == exchange::CellInput::grain_size)
    check(solid, solid.writes, f::grain_size, 1, intensive, state);
  if (law_->cell_input() == exchange::CellInput::permeability)
    check(solid, solid.writes, f::permeability, 1, intensive, state);
  check(fluid, fluid.writes, f::fluid_velocity, dim, intensive, state);
  check(fluid, fluid.writes, f::fluid_bulk_density, 1, intensive, state);
  const auto extensive = Quantity::extensive;
  const auto integral = TimeTreatment::integral;
  check(solid, solid.reads, f::impulse, dim, extensive, integral);
  if (spec_.solved_by == job::ExchangeSolver::coupler) {
    check(fluid, fluid.reads, f::impulse, dim, extensive, integral);
  } else {
    check(fluid, fluid.reads, f::drag_coefficient, 1, intensive, state);
    check(fluid, fluid.writes, f::impulse, dim, extensive, integral);
  }
}

MomentumExchangeStep::Impulses MomentumExchangeStep::run(double window, const PhaseSide& fluid,
                                                         const PhaseSide& solid,
                                                         OperatorCache& operators) const {
  if (spec_.solved_by == job::ExchangeSolver::fluid)
    return run_in_fluid(window, fluid, solid, operators);
  const PhaseSide& owner = spec_.mesh_owner == spec_.fluid ? fluid : solid;
  const Mesh& exchange_mesh = owner.mesh(spec_.mesh);
  const std::size_t exchange_version = owner.version(spec_.mesh);
  const int dim = exchange_mesh.dimension();
  const std::size_t cells = exchange_mesh.size();

  // A phase's field, mapped consistently onto the exchange mesh.
  auto on_exchange_mesh = [&](const PhaseSide& side, const char* field, int components) {
    const std::string& mesh = side.spec->writes.at(field);
    const auto& op =
        operators.get(fmt::format("momentum:{}.{}->exchange", side.spec->name, mesh),
                      side.mesh(mesh), side.version(mesh), exchange_mesh, exchange_version,
                      mapping::Constraint::consistent, mapping::Kernel::linear);
    return op.apply(side.written->at(field), components);
  };
  const auto phi_s = on_exchange_mesh(solid, f::solid_fraction, 1);
  const auto u_s = on_exchange_mesh(solid, f::solid_velocity, dim);
  const auto rho_s = on_exchange_mesh(solid, f::solid_bulk_density, 1);
  const auto u_f = on_exchange_mesh(fluid, f::fluid_velocity, dim);
  const auto rho_f = on_exchange_mesh(fluid, f::fluid_bulk_density, 1);
  std::vector<double> grain, permeability;
  if (law_->cell_input() == exchange::CellInput::grain_size)
    grain = on_exchange_mesh(solid, f::grain_size, 1);
  if (law_->cell_input() == exchange::CellInput::permeability)
    permeability = on_exchange_mesh(solid, f::permeability, 1);

  std::vector<double> volume(cells);
  for (std::size_t c = 0; c < cells; ++c) volume[c] = exchange_mesh.control_volume(c);
  const std::size_t n = cells * static_cast<std::size_t>(dim);
  std::vector<double> du_f(n), du_s(n), j_f(n), j_s(n);
  exchange::exchange_two_phase(*law_, dim, window, volume, {rho_f, u_f}, {rho_s, u_s},
                               {phi_s, grain, permeability}, {du_f, du_s, j_f, j_s, {}});

  // The momentum each phase receives, mapped conservatively to it.
  auto to_side = [&](const PhaseSide& side, const std::vector<double>& impulse) {
    const std::string& mesh = side.spec->reads.at(f::impulse);
    const auto& op =
        operators.get(fmt::format("momentum:exchange->{}.{}", side.spec->name, mesh), exchange_mesh,
                      exchange_version, side.mesh(mesh), side.version(mesh),
                      mapping::Constraint::conservative, mapping::Kernel::linear);
    return op.apply(impulse, dim);
  };
  Impulses out;
  out.fluid = to_side(fluid, j_f);
  out.solid = to_side(solid, j_s);
  double net = 0.0, scale = 0.0;
  for (double j : out.fluid) {
    net += j;
    scale += std::abs(j);
  }
  for (double j : out.solid) net += j;
  out.momentum_balance_error = scale > 0.0 ? std::abs(net) / scale : 0.0;
  return out;
}

MomentumExchangeStep::Impulses MomentumExchangeStep::run_in_fluid(double window,
                                                                  const PhaseSide& fluid,
                                                                  const PhaseSide& solid,
                                                                  OperatorCache& operators) const {
  const PhaseSide& owner = spec_.mesh_owner == spec_.fluid ? fluid : solid;
  const Mesh& exchange_mesh = owner.mesh(spec_.mesh);
  const std::size_t exchange_version = owner.version(spec_.mesh);
  const int dim = exchange_mesh.dimension();
  const std::size_t cells = exchange_mesh.size();

  auto consistent = [&](const std::string& key, const Mesh& from, std::size_t from_version,
                        const Mesh& to, std::size_t to_version) -> const mapping::Operator& {
    return operators.get(key, from, from_version, to, to_version, mapping::Constraint::consistent,
                         mapping::Kernel::linear);
  };
  auto on_exchange_mesh = [&](const PhaseSide& side, const char* field, int components) {
    const std::string& mesh = side.spec->writes.at(field);
    return consistent(fmt::format("momentum:{}.{}->exchange", side.spec->name, mesh),
                      side.mesh(mesh), side.version(mesh), exchange_mesh, exchange_version)
        .apply(side.written->at(field), components);
  };
  const auto phi_s = on_exchange_mesh(solid, f::solid_fraction, 1);
  const auto u_s = on_exchange_mesh(solid, f::solid_velocity, dim);
  const auto rho_s = on_exchange_mesh(solid, f::solid_bulk_density, 1);
  const auto u_f = on_exchange_mesh(fluid, f::fluid_velocity, dim);
  const auto rho_f = on_exchange_mesh(fluid, f::fluid_bulk_density, 1);
  std::vector<double> grain, permeability;
  if (law_->cell_input() == exchange::CellInput::grain_size)
    grain = on_exchange_mesh(solid, f::grain_size, 1);
  if (law_->cell_input() == exchange::CellInput::permeability)
    permeability = on_exchange_mesh(solid, f::permeability, 1);

  // K from the law with the window-end fields (the exchange itself, whose
  // increments are discarded, checks every input as in coupler mode).
  std::vector<double> volume(cells);
  for (std::size_t c = 0; c < cells; ++c) volume[c] = exchange_mesh.control_volume(c);
  const std::size_t n = cells * static_cast<std::size_t>(dim);
  std::vector<double> du_f(n), du_s(n), j_f(n), j_s(n), drag(cells);
  exchange::exchange_two_phase(*law_, dim, window, volume, {rho_f, u_f}, {rho_s, u_s},
                               {phi_s, grain, permeability}, {du_f, du_s, j_f, j_s, drag});
  for (double& k : drag) k = std::min(k, impermeable_drag);

  Impulses out;
  const std::string& drag_mesh = fluid.spec->reads.at(f::drag_coefficient);
  out.drag_coefficient =
      consistent(fmt::format("momentum:exchange->{}.{}", fluid.spec->name, drag_mesh),
                 exchange_mesh, exchange_version, fluid.mesh(drag_mesh), fluid.version(drag_mesh))
          .apply(drag, 1);

  const std::string& from_mesh = fluid.spec->writes.at(f::impulse);
  const std::string& to_mesh = solid.spec->reads.at(f::impulse);
  const std::vector<double>& given = fluid.written->at(f::impulse);
  out.solid =
      operators
          .get(fmt::format("momentum:{}.{}->{}.{}", fluid.spec->name, from_mesh, solid.spec->name,
                           to_mesh),
               fluid.mesh(from_mesh), fluid.version(from_mesh), solid.mesh(to_mesh),
               solid.version(to_mesh), mapping::Constraint::conservative, mapping::Kernel::linear)
          .apply(given, dim);
  double scale = 0.0, net = 0.0;
  for (double j : given) {
    scale += std::abs(j);
    net -= j;
  }
  for (double j : out.solid) net += j;
  out.momentum_balance_error = scale > 0.0 ? std::abs(net) / scale : 0.0;
  return out;
}

}  // namespace cosim::cplscheme

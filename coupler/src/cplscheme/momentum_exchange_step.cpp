#include "momentum_exchange_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"
#include "cosim/fields.hpp"
#include "exchange/drag_law_registry.hpp"
#include "exchange/two_phase_exchange.hpp"

namespace cosim::cplscheme {

namespace f = fields;

namespace {

const FieldSpec* find(const std::vector<FieldSpec>& fields, const std::string& name) {
  auto it = std::find_if(fields.begin(), fields.end(), [&](auto& x) { return x.name == name; });
  return it == fields.end() ? nullptr : &*it;
}

// The mesh a phase writes `field` on: the job's, or for a field the job does
// not list (an optional write), the participant's own declaration.
const std::string* mesh_of(const PhaseSide& side, const std::string& field) {
  if (auto it = side.spec->writes.find(field); it != side.spec->writes.end()) return &it->second;
  if (const FieldSpec* declared = find(side.hello->writes, field)) return &declared->mesh;
  return nullptr;
}

// The exchange mesh of a window: its owner's mesh and version.
struct ExchangeMesh {
  MeshName name;
  const Mesh& mesh;
  std::size_t version = 0;
};

ExchangeMesh exchange_mesh_of(const job::MomentumExchangeSpec& spec, const PhaseSide& fluid,
                              const PhaseSide& solid) {
  const PhaseSide& owner = spec.mesh_owner == spec.fluid ? fluid : solid;
  return {{spec.mesh_owner, spec.mesh}, owner.mesh(spec.mesh), owner.version(spec.mesh)};
}

// A phase's field mapped consistently onto the exchange mesh.
std::vector<double> on_exchange_mesh(const PhaseSide& side, const std::string& field,
                                     int components, const ExchangeMesh& exchange_cells,
                                     OperatorCache& operators) {
  const std::string& mesh = *mesh_of(side, field);
  const OperatorKey key{{side.spec->name, mesh},
                        exchange_cells.name,
                        mapping::Constraint::consistent,
                        mapping::Kernel::linear};
  return operators
      .get(key, side.mesh(mesh), side.version(mesh), exchange_cells.mesh, exchange_cells.version)
      .apply(side.written->at(field), components);
}

// U* = U - j / (rho_bar V) per exchange cell: the velocity a phase would have
// reached without the momentum it was given (none where the phase is absent).
void predicted_velocity(const Mesh& cells, std::span<const double> bulk_density,
                        std::span<const double> given, std::vector<double>& velocity) {
  if (given.size() != velocity.size()) return;  // the first window: nothing given yet
  const std::size_t dim = velocity.size() / std::max<std::size_t>(bulk_density.size(), 1);
  for (std::size_t c = 0; c < bulk_density.size(); ++c) {
    const double mass = bulk_density[c] * cells.control_volume(c);
    if (!(mass > 0.0)) continue;
    for (std::size_t k = 0; k < dim; ++k) velocity[c * dim + k] -= given[c * dim + k] / mass;
  }
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
  auto check = [&](const com::Hello& hello, const std::vector<FieldSpec>& declared,
                   const fields::Field& needed) {
    const FieldSpec* field = find(declared, needed.name);
    if (!field)
      fail(fmt::format("participant '{}' does not declare '{}'", hello.participant, needed.name));
    const int components = needed.components_in(dim);
    if (field->components != components || field->quantity != needed.quantity ||
        field->time != needed.time)
      fail(fmt::format(
          "participant '{}' declares '{}' as {} {} with {} components; the exchange "
          "needs {} {} with {}",
          hello.participant, needed.name, to_string(field->quantity), to_string(field->time),
          field->components, to_string(needed.quantity), to_string(needed.time), components));
  };
  check(solid, solid.writes, f::solid_fraction);
  check(solid, solid.writes, f::solid_velocity);
  check(solid, solid.writes, f::solid_bulk_density);
  if (law_->cell_input() == exchange::CellInput::grain_size)
    check(solid, solid.writes, f::grain_size);
  if (law_->cell_input() == exchange::CellInput::permeability)
    check(solid, solid.writes, f::permeability);
  check(fluid, fluid.writes, f::fluid_velocity);
  check(fluid, fluid.writes, f::fluid_bulk_density);
  check(solid, solid.reads, f::momentum_exchange_impulse);
  if (spec_.solved_by == job::ExchangeSolver::coupler) {
    check(fluid, fluid.reads, f::momentum_exchange_impulse);
  } else {
    check(fluid, fluid.reads, f::drag_coefficient);
    check(fluid, fluid.writes, f::momentum_exchange_impulse);
  }
}

MomentumExchangeStep::Impulses MomentumExchangeStep::run(
    double window, const PhaseSide& fluid, const PhaseSide& solid, OperatorCache& operators,
    const ExchangeCellImpulses* applied) const {
  const ExchangeMesh exchange_cells = exchange_mesh_of(spec_, fluid, solid);
  const Mesh& exchange_mesh = exchange_cells.mesh;
  const std::size_t exchange_version = exchange_cells.version;
  const int dim = exchange_mesh.dimension();
  const std::size_t cells = exchange_mesh.size();
  auto map = [&](const MeshName& from_name, const Mesh& from, std::size_t from_version,
                 const MeshName& to_name, const Mesh& to, std::size_t to_version,
                 mapping::Constraint constraint, const std::vector<double>& values,
                 int components) {
    const OperatorKey key{from_name, to_name, constraint, mapping::Kernel::linear};
    return operators.get(key, from, from_version, to, to_version).apply(values, components);
  };

  auto mapped = [&](const PhaseSide& side, const char* field, int components) {
    return on_exchange_mesh(side, field, components, exchange_cells, operators);
  };
  const auto phi_s = mapped(solid, f::solid_fraction.name, 1);
  auto u_s = mapped(solid, f::solid_velocity.name, dim);
  const auto rho_s = mapped(solid, f::solid_bulk_density.name, 1);
  auto u_f = mapped(fluid, f::fluid_velocity.name, dim);
  const auto rho_f = mapped(fluid, f::fluid_bulk_density.name, 1);
  if (applied && spec_.solved_by == job::ExchangeSolver::coupler) {
    predicted_velocity(exchange_mesh, rho_f, applied->fluid, u_f);
    predicted_velocity(exchange_mesh, rho_s, applied->solid, u_s);
  }
  std::vector<double> grain, permeability;
  if (law_->cell_input() == exchange::CellInput::grain_size)
    grain = mapped(solid, f::grain_size.name, 1);
  if (law_->cell_input() == exchange::CellInput::permeability)
    permeability = mapped(solid, f::permeability.name, 1);

  std::vector<double> volume(cells);
  for (std::size_t c = 0; c < cells; ++c) volume[c] = exchange_mesh.control_volume(c);
  const std::size_t n = cells * static_cast<std::size_t>(dim);
  std::vector<double> du_f(n), du_s(n), j_f(n), j_s(n), drag(cells);
  exchange::exchange_two_phase(*law_, dim, window, volume, {rho_f, u_f}, {rho_s, u_s},
                               {phi_s, grain, permeability}, {du_f, du_s, j_f, j_s, drag});

  // What each phase receives, mapped to it: the momentum (conservatively),
  // or with solved_by fluid K for the fluid (consistently) and, for the
  // solid, the momentum the fluid wrote that it gave it.
  auto impulse_to = [&](const PhaseSide& side, const MeshName& from_name, const Mesh& from,
                        std::size_t from_version, const std::vector<double>& impulse) {
    const std::string& mesh = side.spec->reads.at(f::momentum_exchange_impulse.name);
    return map(from_name, from, from_version, {side.spec->name, mesh}, side.mesh(mesh),
               side.version(mesh), mapping::Constraint::conservative, impulse, dim);
  };
  Impulses out;
  const std::vector<double>* given = &j_f;
  if (spec_.solved_by == job::ExchangeSolver::coupler) out.on_exchange_mesh = {j_f, j_s};
  if (spec_.solved_by == job::ExchangeSolver::coupler) {
    out.fluid = impulse_to(fluid, exchange_cells.name, exchange_mesh, exchange_version, j_f);
    out.solid = impulse_to(solid, exchange_cells.name, exchange_mesh, exchange_version, j_s);
  } else {
    // The law gives +infinity where no pore is left; the fluid gets a
    // finite impermeable value.
    for (double& k : drag) k = std::min(k, impermeable_drag);
    const std::string& drag_mesh = fluid.spec->reads.at(f::drag_coefficient.name);
    out.drag_coefficient = map(exchange_cells.name, exchange_mesh, exchange_version,
                               {fluid.spec->name, drag_mesh}, fluid.mesh(drag_mesh),
                               fluid.version(drag_mesh), mapping::Constraint::consistent, drag, 1);
    const std::string& from_mesh = fluid.spec->writes.at(f::momentum_exchange_impulse.name);
    given = &fluid.written->at(f::momentum_exchange_impulse.name);
    out.solid = impulse_to(solid, {fluid.spec->name, from_mesh}, fluid.mesh(from_mesh),
                           fluid.version(from_mesh), *given);
  }
  // The balance: coupler mode, what the two receive adds up to zero; fluid
  // mode, the solid receives what the fluid gave (the fluid's loss is -given).
  const double sign = spec_.solved_by == job::ExchangeSolver::coupler ? 1.0 : -1.0;
  double net = 0.0, scale = 0.0;
  for (double j : spec_.solved_by == job::ExchangeSolver::coupler ? out.fluid : *given) {
    net += sign * j;
    scale += std::abs(j);
  }
  for (double j : out.solid) net += j;
  out.momentum_balance_error = scale > 0.0 ? std::abs(net) / scale : 0.0;
  return out;
}

}  // namespace cosim::cplscheme

namespace cosim::cplscheme {

std::optional<ExplicitStabilityBound> MomentumExchangeStep::explicit_window_bound(
    const PhaseSide& fluid, const PhaseSide& solid, OperatorCache& operators) const {
  if (!mesh_of(fluid, f::pore_fluid_bulk_modulus.name) ||
      !fluid.written->count(f::pore_fluid_bulk_modulus.name))
    return std::nullopt;
  const ExchangeMesh exchange_cells = exchange_mesh_of(spec_, fluid, solid);
  auto mapped = [&](const PhaseSide& side, const char* field) {
    return on_exchange_mesh(side, field, 1, exchange_cells, operators);
  };
  return undrained_wave_bound(exchange_cells.mesh, mapped(solid, f::solid_fraction.name),
                              mapped(solid, f::solid_bulk_density.name),
                              mapped(fluid, f::fluid_bulk_density.name),
                              mapped(fluid, f::pore_fluid_bulk_modulus.name));
}

}  // namespace cosim::cplscheme

#include "ice/solver/ice_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cosim/error.hpp"
#include "cosim/exchange/implicit_exchange.hpp"
#include "ice/advection/advection_time_step.hpp"
#include "ice/eos/model_dispatch.hpp"
#include "ice/grid/face_walk.hpp"

namespace ice {

namespace {

void check_porosity(std::span<const double> porosity) {
  for (std::size_t c = 0; c < porosity.size(); ++c) {
    const double n = porosity[c];
    if (!(n > 0.0 && n <= 1.0)) {
      throw cosim::NumericalError(
          fmt::format("ICE: porosity {} in cell {} is outside (0, 1]", n, c));
    }
  }
}

// Eqs. 44-45 on the interior faces first <= f < end of a row (upper cell
// f - upper_offset, lower one stride below); see compute_face_velocities.
// A function of its own, with restrict-qualified outputs, so that the loop
// vectorises.
inline void interior_face_velocities(int first, int end, int upper_offset, int stride, double dt,
                                     double dx, double g, const double* __restrict rhobar,
                                     const double* __restrict phi, const double* __restrict u,
                                     const double* __restrict p, double* __restrict face_u,
                                     double* __restrict face_v) {
  for (int f = first; f < end; ++f) {
    const int upper = f - upper_offset;
    const int lower = upper - stride;
    const double rb_l = rhobar[lower];
    const double rb_r = rhobar[upper];
    const double v_face = (phi[lower] + phi[upper]) / (rb_l + rb_r);
    const double mean_u = (rb_l * u[lower] + rb_r * u[upper]) / (rb_l + rb_r);
    const double gradient = (p[upper] - p[lower]) / dx;
    face_u[f] = mean_u + dt * (-v_face * gradient + g);
    face_v[f] = v_face;
  }
}

// compute_lagrangian_energy's cells first <= c < end of a row along x:
// the face arrays are offset so that cell c's lower face normal to d is
// index c and its upper face c + stride[d]. A function of its own, with
// restrict-qualified outputs, so that the loop vectorises; returns how many
// cells were left without positive finite internal energy.
template <int Dim>
struct LagrangianEnergyRow {
  std::array<const double*, static_cast<std::size_t>(Dim)> face_pressure{};
  // The volume fraction the pressure equation carried on each face
  // (face_fraction) and U_f,FC: their product is the face's volume flux.
  std::array<const double*, static_cast<std::size_t>(Dim)> face_fraction{};
  std::array<const double*, static_cast<std::size_t>(Dim)> face_velocity{};
  std::array<int, static_cast<std::size_t>(Dim)> stride{};
  std::array<double, static_cast<std::size_t>(Dim)> spacing{};
  std::array<const double*, static_cast<std::size_t>(Dim)> velocity{};
  std::array<const double*, static_cast<std::size_t>(Dim)> momentum{};
};

template <int Dim>
int lagrangian_energy_row(const LagrangianEnergyRow<Dim>& pointers, int first, int end, double dt,
                          double c_v, const double* __restrict bulk_density,
                          const double* __restrict volume_fraction, const double* __restrict kappa,
                          const double* __restrict pressure_increment,
                          const double* __restrict new_pressure,
                          const double* __restrict temperature, double* __restrict energy) {
  const LagrangianEnergyRow<Dim> row = pointers;  // a local copy: kept in registers
  // Counted in a double (exact to 2^53): GCC vectorises this reduction, not
  // one into an integer.
  double refused = 0.0;
  for (int c = first; c < end; ++c) {
    const double rhobar = bulk_density[c];
    const double phi = volume_fraction[c];
    double work = 0.0;
    double volume_flux = 0.0;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
      const double p_low = row.face_pressure[d][c];
      const double p_up = row.face_pressure[d][c + row.stride[d]];
      const double u = row.velocity[d][c];
      const double u_mid = u + 0.5 * (row.momentum[d][c] / rhobar - u);
      const double flux_low = row.face_fraction[d][c] * row.face_velocity[d][c];
      const double flux_up =
          row.face_fraction[d][c + row.stride[d]] * row.face_velocity[d][c + row.stride[d]];
      work += (phi * (p_up - p_low) * u_mid - (p_up * flux_up - p_low * flux_low)) / row.spacing[d];
      volume_flux += (flux_up - flux_low) / row.spacing[d];
    }
    // The material's share of the volume work: its own compression
    // -phi_f kappa_f dP instead of its volume outflow dt div(phi_f U_f);
    // the difference sums to zero over the materials by eq. 125.
    const double share =
        new_pressure[c] * (phi * kappa[c] * pressure_increment[c] + dt * volume_flux);
    energy[c] = rhobar * c_v * temperature[c] + dt * work + share;
    // Positive and finite: 0 < e <= the largest double (comparisons only,
    // combined with & rather than && so that no branch is needed).
    const bool positive_finite =
        (energy[c] > 0.0) & (energy[c] <= std::numeric_limits<double>::max());
    refused += positive_finite ? 0.0 : 1.0;
  }
  return refused > 0.0 ? 1 : 0;
}

// advect_and_update's pass over one material's cells after its advection:
// with `total_energy` the kinetic energy the advection dissipated returns
// to the internal energy, then the bulk density, velocity, temperature and
// specific volume. Restrict-qualified and branch-free (a cell without mass
// gets quotients the check reports), so that the loop vectorises; returns
// how many cells have no positive finite mass or temperature.
template <int Dim, bool total_energy>
int primitive_variables(std::size_t cells, double c_v,
                        const std::array<const double*, static_cast<std::size_t>(Dim)>& momentum,
                        const std::array<double*, static_cast<std::size_t>(Dim)>& velocity,
                        const double* __restrict mass, const double* __restrict kinetic,
                        const double* __restrict volume, double* __restrict energy,
                        double* __restrict bulk_density, double* __restrict temperature,
                        double* __restrict specific_volume) {
  constexpr double largest = std::numeric_limits<double>::max();
  const auto mom = momentum;  // local copies of the pointers: kept in registers
  const auto u = velocity;
  double bad = 0.0;  // a double count, so that it vectorises (see above)
  for (std::size_t c = 0; c < cells; ++c) {
    const double m = mass[c];
    double twice = 0.0;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
      twice += mom[d][c] * mom[d][c];
      u[d][c] = mom[d][c] / m;
    }
    const double kinetic_after = 0.5 * twice / m;
    // A cell without mass fails the check below (its energy is not used).
    const double e = total_energy ? energy[c] + (kinetic[c] - kinetic_after) : energy[c];
    energy[c] = e;
    bulk_density[c] = m;
    const double t = e / (m * c_v);
    temperature[c] = t;
    specific_volume[c] = volume[c] / m;
    const bool good = (m > 0.0) & (m <= largest) & (t > 0.0) & (t <= largest);
    bad += good ? 0.0 : 1.0;
  }
  return bad > 0.0 ? 1 : 0;
}

void require(bool condition, const std::string& what) {
  if (!condition) throw std::invalid_argument("IceSolver: " + what);
}

}  // namespace

std::string to_string(SideType type) {
  switch (type) {
    case SideType::wall:
      return "wall";
    case SideType::outflow:
      return "outflow";
    case SideType::fixed_pressure:
      return "fixed_pressure";
    case SideType::inflow:
      return "inflow";
  }
  return "unknown";
}

template <int Dim>
IceSolver<Dim>::IceSolver(const CellGrid<Dim>& grid, std::vector<FluidMaterial> materials,
                          ExchangeCoefficients exchange, const Sides& sides, const Vector& gravity,
                          FluidState<Dim> state, IceSolverOptions options)
    : grid_(grid),
      materials_(std::move(materials)),
      exchange_(std::move(exchange)),
      sides_(sides),
      gravity_(gravity),
      options_(options),
      state_(std::move(state)),
      pressure_solver_(grid, pressure_boundaries(sides), options.pressure),
      advector_(grid, options.limiter),
      diffusion_(grid, sides) {
  const std::size_t n = materials_.size();
  const std::size_t cells = at(grid_.cell_count());
  drag_share_.assign(n, 1.0);
  require(n >= 1, "at least one material is needed");
  require(n <= static_cast<std::size_t>(cosim::exchange::kMaxMaterials),
          fmt::format("at most {} materials", cosim::exchange::kMaxMaterials));
  require(exchange_.materials == static_cast<int>(n) && exchange_.momentum.size() == n * n &&
              exchange_.heat.size() == n * n,
          "exchange coefficients must be N x N for the N materials");
  require(state_.materials.size() == n, "the state must hold every material");
  require(options_.max_courant > 0.0 && options_.max_courant <= 1.0,
          "max_courant must lie in (0, 1]");
  for (std::size_t i = 0; i < n * n; ++i) {
    require(std::isfinite(exchange_.momentum[i]) && exchange_.momentum[i] >= 0.0 &&
                std::isfinite(exchange_.heat[i]) && exchange_.heat[i] >= 0.0,
            "exchange coefficients must be finite and >= 0");
    if (i % (n + 1) != 0) {
      has_momentum_exchange_ = has_momentum_exchange_ || exchange_.momentum[i] > 0.0;
      has_heat_exchange_ = has_heat_exchange_ || exchange_.heat[i] > 0.0;
    }
  }
  for (const FluidMaterial& material : materials_) {
    require(material.eos != nullptr, "material '" + material.name + "' has no equation of state");
    require(material.viscosity >= 0.0 && material.thermal_conductivity >= 0.0,
            "material '" + material.name + "' has a negative viscosity or conductivity");
    viscous_ = viscous_ || material.viscosity > 0.0 || options_.smagorinsky_constant > 0.0;
    conducting_ = conducting_ || material.thermal_conductivity > 0.0;
    eos_.push_back(material.eos.get());
  }
  if (state_.porosity.empty()) state_.porosity.assign(cells, 1.0);
  for (auto& component : state_.solid_velocity) {
    if (component.empty()) component.assign(cells, 0.0);
  }
  require(state_.porosity.size() == cells, "porosity needs one value per cell");
  for (const auto& component : state_.solid_velocity) {
    require(component.size() == cells, "solid velocity needs one value per cell");
  }
  require(state_.pressure.empty() || state_.pressure.size() == cells,
          "pressure needs one value per cell or none");
  for (std::size_t m = 0; m < n; ++m) {
    MaterialState<Dim>& material = state_.materials[m];
    require(material.bulk_density.size() == cells && material.temperature.size() == cells,
            "material '" + materials_[m].name + "' needs bulk density and temperature per cell");
    for (const auto& component : material.velocity) {
      require(component.size() == cells,
              "material '" + materials_[m].name + "' needs its velocity per cell");
    }
  }

  owned_.assign(cells, 1);
  kappa_.assign(n, CellField(cells, 0.0));
  face_velocity_.assign(n, make_face_field(grid_));
  face_correction_.assign(n, make_face_field(grid_));
  mixture_kappa_.assign(cells, 0.0);
  face_density_ = make_face_field(grid_, 1.0);
  mixture_velocity_ = make_face_field(grid_);
  solid_face_velocity_ = make_face_field(grid_);
  solid_face_fraction_ = make_face_field(grid_);
  face_fraction_.assign(n, make_face_field(grid_));
  previous_face_velocity_.assign(n, make_face_field(grid_));
  face_pressure_ = make_face_field(grid_);
  scratch_face_ = make_face_field(grid_, 1.0);
  pressure_increment_.assign(cells, 0.0);
  new_pressure_.assign(cells, 0.0);
  mass_.assign(n, CellField(cells, 0.0));
  momentum_.resize(n);
  for (auto& m : momentum_) {
    for (auto& component : m) component.assign(cells, 0.0);
  }
  energy_.assign(n, CellField(cells, 0.0));
  volume_.assign(n, CellField(cells, 0.0));
  kinetic_.assign(n, CellField(cells, 0.0));
  lagrangian_temperature_.assign(n, CellField(cells, 0.0));

  check_state(state_);
  equilibrate(nullptr);
  for (std::size_t m = 0; m < n; ++m) {
    MaterialState<Dim>& material = state_.materials[m];
    material.specific_volume.resize(cells);
    for (std::size_t c = 0; c < cells; ++c) material.specific_volume[c] = 1.0 / material.density[c];
  }
}

template <int Dim>
void IceSolver<Dim>::check_state(const FluidState<Dim>& state) const {
  check_porosity(state.porosity);
  for (std::size_t m = 0; m < state.materials.size(); ++m) {
    const MaterialState<Dim>& material = state.materials[m];
    for (std::size_t c = 0; c < material.bulk_density.size(); ++c) {
      if (!(material.bulk_density[c] > 0.0) || !std::isfinite(material.bulk_density[c])) {
        throw cosim::NumericalError(fmt::format(
            "ICE: material '{}' has bulk density {} in cell {} (must be positive: every material "
            "keeps a small volume fraction everywhere)",
            materials_[m].name, material.bulk_density[c], c));
      }
      if (!(material.temperature[c] > 0.0) || !std::isfinite(material.temperature[c])) {
        throw cosim::NumericalError(
            fmt::format("ICE: material '{}' has temperature {} K in cell {}", materials_[m].name,
                        material.temperature[c], c));
      }
    }
  }
}

template <int Dim>
void IceSolver<Dim>::set_porous_medium(
    std::span<const double> porosity,
    const std::array<CellField, static_cast<std::size_t>(Dim)>& solid_velocity,
    PorosityChange change) {
  const std::size_t cells = at(grid_.cell_count());
  require(porosity.size() == cells, "porosity needs one value per cell");
  for (const auto& component : solid_velocity) {
    require(component.size() == cells, "solid velocity needs one value per cell");
  }
  state_.solid_velocity = solid_velocity;
  solid_exchange_velocity_ = solid_velocity;
  if (change == PorosityChange::displace) {
    check_porosity(porosity);
    porosity_to_displace_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c)
      porosity_to_displace_[c] = porosity[c] - state_.porosity[c];
    return;
  }
  porosity_to_displace_.clear();
  if (change == PorosityChange::fill_pores) {
    for (std::size_t c = 0; c < cells; ++c) {
      const double ratio = porosity[c] / state_.porosity[c];
      if (!(ratio > 0.0) || !std::isfinite(ratio)) continue;  // check_state reports it
      for (MaterialState<Dim>& material : state_.materials) material.bulk_density[c] *= ratio;
    }
  }
  state_.porosity.assign(porosity.begin(), porosity.end());
  check_state(state_);
  equilibrate(nullptr);
}

template <int Dim>
void IceSolver<Dim>::set_solid_drag(std::span<const double> drag_coefficient,
                                    std::span<const double> solid_bulk_density) {
  const std::size_t cells = at(grid_.cell_count());
  if (drag_coefficient.empty() && solid_bulk_density.empty()) {
    solid_drag_on_ = false;
    return;
  }
  require(drag_coefficient.size() == cells && solid_bulk_density.size() == cells,
          "drag coefficient and solid bulk density need one value per cell");
  for (std::size_t c = 0; c < cells; ++c) {
    if (!(drag_coefficient[c] >= 0.0) || !std::isfinite(drag_coefficient[c]) ||
        !(solid_bulk_density[c] >= 0.0) || !std::isfinite(solid_bulk_density[c])) {
      throw cosim::NumericalError(fmt::format(
          "ICE: cell {} received drag coefficient {} kg/(m3 s) and solid bulk density {} kg/m3 "
          "(both must be finite and >= 0)",
          c, drag_coefficient[c], solid_bulk_density[c]));
    }
  }
  solid_drag_.assign(drag_coefficient.begin(), drag_coefficient.end());
  solid_bulk_density_.assign(solid_bulk_density.begin(), solid_bulk_density.end());
  solid_impulse_.resize(cells * static_cast<std::size_t>(Dim), 0.0);
  solid_drag_on_ = true;
}

template <int Dim>
void IceSolver<Dim>::set_drag_viscosity(double viscosity) {
  if (!(viscosity >= 0.0) || !std::isfinite(viscosity)) {
    throw std::invalid_argument(
        fmt::format("IceSolver: the drag's viscosity {} Pa s must be finite and >= 0", viscosity));
  }
  drag_share_.assign(count(), 1.0);
  if (viscosity == 0.0) return;
  for (std::size_t m = 0; m < count(); ++m) {
    if (!(materials_[m].viscosity > 0.0)) {
      throw std::invalid_argument(
          fmt::format("IceSolver: material '{}' has no viscosity to scale the drag of {} Pa s by",
                      materials_[m].name, viscosity));
    }
    drag_share_[m] = materials_[m].viscosity / viscosity;
  }
}

template <int Dim>
void IceSolver<Dim>::take_solid_impulse(std::span<double> impulse) {
  const std::size_t size = at(grid_.cell_count()) * static_cast<std::size_t>(Dim);
  require(impulse.size() == size, "the solid impulse needs Dim values per cell");
  solid_impulse_.resize(size, 0.0);
  std::copy(solid_impulse_.begin(), solid_impulse_.end(), impulse.begin());
  std::fill(solid_impulse_.begin(), solid_impulse_.end(), 0.0);
}

template <int Dim>
void IceSolver<Dim>::solid_pressure_force(std::span<double> force) const {
  const auto dim = static_cast<std::size_t>(Dim);
  require(force.size() == at(grid_.cell_count()) * dim, "the force needs Dim values per cell");
  const double volume = grid_.cell_volume();
  for (int c = 0; c < grid_.cell_count(); ++c) {
    const double solid = 1.0 - state_.porosity[at(c)];
    for (int d = 0; d < Dim; ++d) {
      const double gradient = (face_pressure_[at(d)][at(grid_.upper_face(d, c))] -
                               face_pressure_[at(d)][at(grid_.lower_face(d, c))]) /
                              grid_.spacing()[d];
      force[at(c) * dim + at(d)] = -solid * gradient * volume;
    }
  }
}

template <int Dim>
void IceSolver<Dim>::add_heat(std::span<const double> heat) {
  const std::size_t cells = at(grid_.cell_count());
  require(heat.size() == cells, "heat needs one value per cell");
  const double volume = grid_.cell_volume();
  for (std::size_t c = 0; c < cells; ++c) {
    double capacity = 0.0;
    for (std::size_t m = 0; m < count(); ++m)
      capacity += state_.materials[m].bulk_density[c] * eos_[m]->specific_heat();
    const double warming = heat[c] / (capacity * volume);
    if (!std::isfinite(warming)) {
      throw cosim::NumericalError(
          fmt::format("ICE: heat {} J added to cell {} is not finite", heat[c], c));
    }
    for (MaterialState<Dim>& material : state_.materials) {
      material.temperature[c] += warming;
      if (!(material.temperature[c] > 0.0)) {
        throw cosim::NumericalError(fmt::format("ICE: heat {} J leaves cell {} at temperature {} K",
                                                heat[c], c, material.temperature[c]));
      }
    }
  }
  equilibrate(nullptr);
}

template <int Dim>
void IceSolver<Dim>::add_momentum(std::span<const double> momentum) {
  const auto dim = static_cast<std::size_t>(Dim);
  const std::size_t cells = at(grid_.cell_count());
  require(momentum.size() == cells * dim, "momentum needs Dim values per cell");
  const double volume = grid_.cell_volume();
  for (std::size_t c = 0; c < cells; ++c) {
    double mass = 0.0;
    for (const MaterialState<Dim>& material : state_.materials) mass += material.bulk_density[c];
    mass *= volume;
    for (std::size_t d = 0; d < dim; ++d) {
      const double impulse = momentum[c * dim + d];
      if (!std::isfinite(impulse)) {
        throw cosim::NumericalError(
            fmt::format("ICE: momentum {} added to cell {} is not finite", impulse, c));
      }
      for (MaterialState<Dim>& material : state_.materials)
        material.velocity[d][c] += impulse / mass;
    }
  }
}

template <int Dim>
void IceSolver<Dim>::equilibrate(StepReport* report) {
  std::vector<MaterialCells> cells;
  cells.reserve(count());
  for (std::size_t m = 0; m < count(); ++m) {
    cells.push_back({eos_[m], state_.materials[m].bulk_density, state_.materials[m].temperature});
  }
  equilibrate_pressure(cells, state_.porosity, state_.pressure, options_.equilibration,
                       equilibrium_);
  // The results move into the state (swapped: equilibrium_ keeps the old
  // vectors as storage for the next call, which overwrites them).
  state_.pressure.swap(equilibrium_.pressure);
  std::fill(mixture_kappa_.begin(), mixture_kappa_.end(), 0.0);
  for (std::size_t m = 0; m < count(); ++m) {
    MaterialState<Dim>& material = state_.materials[m];
    material.density.swap(equilibrium_.density[m]);
    material.volume_fraction.swap(equilibrium_.volume_fraction[m]);
    const double* rho = material.density.data();
    const double* t = material.temperature.data();
    const double* phi = material.volume_fraction.data();
    double* kappa = kappa_[m].data();
    double* mixture = mixture_kappa_.data();
    visit_model_copy(*eos_[m], [&](const auto& eos) {  // inlined for the built-in models
      for (std::size_t c = 0; c < material.density.size(); ++c) {
        kappa[c] = eos.adiabatic_compressibility(rho[c], t[c]);
        // The fluids' volume changes by -sum_f phi_f kappa_f dP V; with the
        // solid in the divergence this sum (not eq. 52's average over the
        // fluids) is the mixture's compressibility per cell volume.
        mixture[c] += phi[c] * kappa[c];
      }
    });
  }
  if (report != nullptr) report->equilibration_iterations = equilibrium_.most_iterations;
}

template <int Dim>
double IceSolver<Dim>::stable_time_step(double courant, bool acoustic) const {
  double rate = last_face_rate_;
  for (int c = 0; c < grid_.cell_count(); ++c) {
    double sound_speed = 0.0;
    if (acoustic) {
      for (std::size_t m = 0; m < count(); ++m) {
        const MaterialState<Dim>& material = state_.materials[m];
        if (material.volume_fraction[at(c)] < 0.01) continue;
        sound_speed =
            std::max(sound_speed, std::sqrt(eos_[m]->adiabatic_sound_speed_squared(
                                      material.density[at(c)], material.temperature[at(c)])));
      }
    }
    double cell_rate = 0.0;
    for (int d = 0; d < Dim; ++d) {
      double speed = 0.0;
      for (std::size_t m = 0; m < count(); ++m) {
        speed = std::max(speed, std::abs(state_.materials[m].velocity[at(d)][at(c)]));
      }
      cell_rate += (speed + sound_speed) / grid_.spacing()[d];
    }
    rate = std::max(rate, cell_rate);
  }
  rate = max_over_blocks(rate);
  double step = rate > 0.0 ? courant / rate : std::numeric_limits<double>::infinity();
  if (viscous_ || conducting_) {
    // Explicit viscous and conductive fluxes: the largest kinematic viscosity
    // and thermal diffusivity among the materials filling at least 1 % of a cell.
    double diffusivity = 0.0;
    for (std::size_t m = 0; m < count(); ++m) {
      const MaterialState<Dim>& material = state_.materials[m];
      for (std::size_t c = 0; c < material.density.size(); ++c) {
        if (material.volume_fraction[c] < 0.01) continue;
        const double rho = material.density[c];
        diffusivity =
            std::max({diffusivity, materials_[m].viscosity / rho,
                      materials_[m].thermal_conductivity / (rho * eos_[m]->specific_heat())});
      }
    }
    step = std::min(step, diffusion_time_step(grid_, max_over_blocks(diffusivity)));
  }
  return step;
}

template <int Dim>
StepReport IceSolver<Dim>::advance(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument(fmt::format("IceSolver: time step {} must be positive", dt));
  }
  StepReport report;
  compute_face_velocities(dt);
  exchange_face_momentum(dt);
  assemble_divergence(face_velocity_);
  PressureSolution pressure = solve_pressure_increment(dt);
  report.pressure_iterations = pressure.iterations;
  // Where the correction reversed a flow, the divergence is assembled again
  // with the final directions, from the same predicted velocities (a flow
  // whose upwind side flips from step to step would otherwise carry volume
  // its mass flux does not, in a two-step cycle).
  for (int pass = 0; pass < 2 && upwind_side_changed(dt); ++pass) {
    flow_direction_ = face_velocity_;
    correct_face_velocities(dt, -1.0);  // back to the predicted velocities
    assemble_divergence(flow_direction_);
    pressure = solve_pressure_increment(dt);
    report.pressure_iterations += pressure.iterations;
  }
  report.pressure_residual = pressure.relative_residual;
  report.courant = face_courant(dt);
  if (report.courant > options_.max_courant) {
    report.accepted = false;
    return report;
  }
  last_face_rate_ = report.courant / dt;
  compute_face_pressure();
  compute_lagrangian_values(dt);
  if (viscous_) add_viscous_stress(dt);
  exchange_cell_momentum(dt);
  if (!compute_lagrangian_energy(dt)) {
    report.accepted = false;
    return report;
  }
  if (conducting_) add_heat_conduction(dt);
  exchange_cell_energy(dt);
  compute_lagrangian_specific_volume(dt);
  advect_and_update(dt, report);
  if (solid_drag_on_) previous_face_velocity_ = face_velocity_;
  if (link_) {
    refresh_ghosts();
    report.volume_closure = link_->max(report.volume_closure);
    report.equilibration_iterations =
        static_cast<int>(link_->max(static_cast<double>(report.equilibration_iterations)));
  }
  time_ += dt;
  ++steps_;
  return report;
}

// One interior face of material m in a porous solid (compute_face_velocities).
// The mass-weighted mean is taken of the superficial velocities n U and
// returned to the face's upwind pore space: a steady flow through a jump in
// porosity keeps its face velocity from step to step (the interstitial
// velocities' mean would differ from it by O(1) and act as a spurious
// inertia of (mean - U_FC) / dt, as large as the drag; Darcy flow through a
// column would come out 7 % fast at 10 cells); with n = 1 this is eq. 44.
// Where the drag on a solid holds the fluid, its face velocity starts from
// its own last value rather than from the cells' mean, in the proportion
// K / (K + rhobar |U| / dx) in which the drag outweighs the momentum the flow
// carries across a cell. The cell velocities there carry what advection
// brings them, not what the face fluxes hold (out of a porous column the
// free cell above takes the pores' interstitial velocity), and the
// difference (mean - U_FC) / dt would act as a force no physics gives: a
// checkerboard of pressure and cell velocity beside a drained side.
template <int Dim>
void IceSolver<Dim>::porous_face_velocity(std::size_t m, int d, int f, int lower, int upper,
                                          double dt) {
  const MaterialState<Dim>& material = state_.materials[m];
  const double dx = grid_.spacing()[d];
  const CellField& u = material.velocity[at(d)];
  const double rb_l = material.bulk_density[at(lower)];
  const double rb_r = material.bulk_density[at(upper)];
  const double v_face =
      (material.volume_fraction[at(lower)] + material.volume_fraction[at(upper)]) / (rb_l + rb_r);
  const double n_l = state_.porosity[at(lower)];
  const double n_r = state_.porosity[at(upper)];
  const double superficial =
      (rb_l * n_l * u[at(lower)] + rb_r * n_r * u[at(upper)]) / (rb_l + rb_r);
  double mean_u = superficial / (superficial >= 0.0 ? n_l : n_r);
  if (solid_drag_on_) {
    const double porosity = 0.5 * (n_l + n_r);
    const double fraction =
        0.5 * (material.volume_fraction[at(lower)] + material.volume_fraction[at(upper)]);
    const double k = face_drag(lower, upper, porosity, d, f, previous_face_velocity_) *
                     drag_share_[m] * fraction / porosity;
    const double carried = 0.5 * (rb_l + rb_r) * std::abs(mean_u) / dx;
    const double memory = k > 0.0 ? k / (k + carried) : 0.0;
    mean_u += memory * (previous_face_velocity_[m][at(d)][at(f)] - mean_u);
  }
  const double gradient = (state_.pressure[at(upper)] - state_.pressure[at(lower)]) / dx;
  face_velocity_[m][at(d)][at(f)] = mean_u + dt * (-v_face * gradient + gravity_[d]);
  face_correction_[m][at(d)][at(f)] = v_face;
}

// Tran et al., MPMICE, eqs. 44-45: per material, the face velocity from the
// mass-weighted cell velocities and the pressure gradient times the face's
// specific volume v_FC = (phi_L + phi_R) / (rhobar_L + rhobar_R). For one
// material (phi = 1) this is eq. 45's 2 v_L v_R / (v_L + v_R) =
// 2 / (rho_L + rho_R); with several it makes rhobar_FC v_FC = phi_FC, so at
// rest the faces balance grad P = g sum_f rhobar_f,FC, the same mixture
// weight that eq. 54's face pressure balances in the cells. (Eq. 45's
// harmonic mean of the intrinsic volumes gives a trace of air on the water
// side of an interface the weight of its neighbour's air and drives a
// current of ~6e-6 m/s at a still water-air surface.)
template <int Dim>
void IceSolver<Dim>::compute_face_velocities(double dt) {
  const FluidState<Dim>& s = state_;
  // Without a porous solid the faces take the vectorised eq. 44 row by row.
  const bool porous = solid_drag_on_ || std::any_of(s.porosity.begin(), s.porosity.end(),
                                                    [](double n) { return n < 1.0; });
  for (std::size_t m = 0; m < count(); ++m) {
    const MaterialState<Dim>& material = s.materials[m];
    for (int d = 0; d < Dim; ++d) {
      const double dx = grid_.spacing()[d];
      const double g = gravity_[d];
      const CellField& u = material.velocity[at(d)];
      std::vector<double>& face_u = face_velocity_[m][at(d)];
      std::vector<double>& face_v = face_correction_[m][at(d)];
      const double* rhobar = material.bulk_density.data();
      const double* phi = material.volume_fraction.data();
      const double* p = s.pressure.data();
      const int stride = grid_.stride(d);
      const auto interior = [&](int first, int end, int upper_offset) {
        if (!porous) {
          interior_face_velocities(first, end, upper_offset, stride, dt, dx, g, rhobar, phi,
                                   u.data(), p, face_u.data(), face_v.data());
          return;
        }
        for (int f = first; f < end; ++f) {
          const int upper = f - upper_offset;
          porous_face_velocity(m, d, f, upper - stride, upper, dt);
        }
      };
      const auto boundary = [&](int f, int cell, bool upper_side) {
        const SideCondition& side = sides_[at(2 * d + (upper_side ? 1 : 0))];
        const double v_cell = 1.0 / material.density[at(cell)];
        face_v[at(f)] = v_cell;
        switch (side.type) {
          case SideType::wall:
            face_u[at(f)] = 0.0;
            break;
          case SideType::outflow:
            face_u[at(f)] = u[at(cell)];
            break;
          case SideType::inflow:
            face_u[at(f)] = side.velocity[at(d)];
            break;
          case SideType::fixed_pressure: {
            const double difference =
                upper_side ? side.pressure - p[cell] : p[cell] - side.pressure;
            face_u[at(f)] = u[at(cell)] + dt * (-v_cell * difference / (0.5 * dx) + g);
            break;
          }
        }
      };
      for_each_face_run(grid_, d, interior, boundary);
    }
  }
}

// The divergence the pressure equation balances: each fluid's volume flux
// takes its upwind cell's volume fraction, the upwind side read off
// `direction`, as the advection of its mass does (eqs. 77-80): with the
// mean of the two cells a steady flow through a jump in porosity would
// carry a volume the mass flux does not, and the pressure beside the jump
// would run away in a checkerboard. Plus the solid's flux.
template <int Dim>
void IceSolver<Dim>::assemble_divergence(const std::vector<FaceField<Dim>>& direction) {
  const std::size_t n = count();
  for (int d = 0; d < Dim; ++d) {
    double* inverse_density = face_density_[at(d)].data();
    double* flux = mixture_velocity_[at(d)].data();
    const double* phi_s = solid_face_fraction_[at(d)].data();
    const double* u_s = solid_face_velocity_[at(d)].data();
    std::array<const double*, cosim::exchange::kMaxMaterials> phi{};
    std::array<const double*, cosim::exchange::kMaxMaterials> sign{};
    std::array<const double*, cosim::exchange::kMaxMaterials> u{};
    std::array<const double*, cosim::exchange::kMaxMaterials> y{};
    std::array<double*, cosim::exchange::kMaxMaterials> carried{};
    for (std::size_t m = 0; m < n; ++m) {
      phi[m] = state_.materials[m].volume_fraction.data();
      sign[m] = direction[m][at(d)].data();
      u[m] = face_velocity_[m][at(d)].data();
      y[m] = face_correction_[m][at(d)].data();
      carried[m] = face_fraction_[m][at(d)].data();
    }
    // 1 / rho_FC = sum_f phi_f,FC y_f and U_FC = phi_s U_s + sum_f phi_f,FC U_f
    // on a face whose materials carry the given fractions.
    const auto sums = [&](int f, const auto& fraction) {
      double inverse = 0.0;
      double volume_flux = phi_s[f] * u_s[f];
      for (std::size_t m = 0; m < n; ++m) {
        const double carried_fraction = fraction(m);
        carried[m][f] = carried_fraction;
        inverse += carried_fraction * y[m][f];
        volume_flux += carried_fraction * u[m][f];
      }
      flux[f] = volume_flux;
      return inverse;
    };
    for_each_face(
        grid_, d,
        [&](int f, int lower, int upper) {
          const double inverse =
              sums(f, [&](std::size_t m) { return phi[m][sign[m][f] >= 0.0 ? lower : upper]; });
          inverse_density[f] = 1.0 / inverse;
        },
        [&](int f, int cell, bool upper_side) {
          const double inverse = sums(f, [&](std::size_t m) { return phi[m][cell]; });
          if (sides_[at(2 * d + (upper_side ? 1 : 0))].type == SideType::wall) {
            inverse_density[f] = 1.0;
            flux[f] = 0.0;
          } else {
            inverse_density[f] = 1.0 / inverse;
          }
        });
  }
}

// Whether the pressure correction turned a face's flow against the upwind
// side the divergence assumed (its carried fraction is not the final
// upwind cell's), by more than a negligible volume.
template <int Dim>
bool IceSolver<Dim>::upwind_side_changed(double dt) const {
  bool changed = false;
  for (std::size_t m = 0; m < count(); ++m) {
    const CellField& phi = state_.materials[m].volume_fraction;
    for (int d = 0; d < Dim; ++d) {
      const double factor = dt / grid_.spacing()[d];
      const double* u = face_velocity_[m][at(d)].data();
      const double* carried = face_fraction_[m][at(d)].data();
      double largest = 0.0;
      for_each_face(
          grid_, d,
          [&](int f, int lower, int upper) {
            if (owned_[at(lower)] == 0 && owned_[at(upper)] == 0) return;
            const double upwind = phi[at(u[f] >= 0.0 ? lower : upper)];
            largest = std::max(largest, std::abs(upwind - carried[f]) * std::abs(u[f]));
          },
          [](int, int, bool) {});
      changed = changed || largest * factor > 1e-10;
    }
  }
  return any_block(changed);
}

// Tran et al., MPMICE, eqs. 52-53 and 125, then each material's face
// velocity corrected with its own coefficient y_f (see above).
template <int Dim>
PressureSolution IceSolver<Dim>::solve_pressure_increment(double dt) {
  // Last step's increment is the initial guess: the pressure changes smoothly.
  // The pores the received medium closes (opens) beyond the solver's own
  // motion of the solid close (open) over this step.
  if (!porosity_to_displace_.empty()) {
    displacement_rate_.resize(porosity_to_displace_.size());
    for (std::size_t c = 0; c < porosity_to_displace_.size(); ++c)
      displacement_rate_[c] = porosity_to_displace_[c] / dt;
  } else {
    displacement_rate_.clear();
  }
  PressureSystemSolver<Dim>& system =
      pressure_system_ ? *pressure_system_
                       : static_cast<PressureSystemSolver<Dim>&>(pressure_solver_);
  const PressureSolution solution = system.solve(mixture_kappa_, face_density_, mixture_velocity_,
                                                 dt, pressure_increment_, displacement_rate_);
  if (link_) {
    const std::span<double> increment[1] = {pressure_increment_};
    link_->fill_ghosts(increment);
  }
  correct_face_velocities(dt, 1.0);
  for (std::size_t c = 0; c < new_pressure_.size(); ++c) {
    new_pressure_[c] = state_.pressure[c] + pressure_increment_[c];
  }
  return solution;
}

// K on a face between two cells. Darcy's law in each half cell,
// grad P = -(K / n^2) q with q = n U the superficial velocity, puts the two
// halves in series, and the face equation K_FC U_FC = -n_FC grad P with
// U_FC = q / n_up (the flux takes the upwind pore space) then needs
//   K_FC = n_FC n_up (K_L / n_L^2 + K_R / n_R^2) / 2,
// which is K inside a uniform medium. At a jump in porosity the mean of the
// two K would leave the first and last faces of a porous column with a
// tenth and a third of their resistance (Darcy flow through ten cells
// 6 % fast).
template <int Dim>
double IceSolver<Dim>::face_drag(int lower, int upper, double face_porosity, int d, int f,
                                 const std::vector<FaceField<Dim>>& velocity) const {
  const double n_l = state_.porosity[at(lower)];
  const double n_r = state_.porosity[at(upper)];
  return face_porosity * fluid_upwind_porosity(lower, upper, d, f, velocity) * 0.5 *
         (solid_drag_[at(lower)] / (n_l * n_l) + solid_drag_[at(upper)] / (n_r * n_r));
}

// The pore space of the cell the fluids' momentum on a face comes from.
template <int Dim>
double IceSolver<Dim>::fluid_upwind_porosity(int lower, int upper, int d, int f,
                                             const std::vector<FaceField<Dim>>& velocity) const {
  double momentum = 0.0;
  for (std::size_t m = 0; m < count(); ++m) {
    momentum += (state_.materials[m].bulk_density[at(lower)] +
                 state_.materials[m].bulk_density[at(upper)]) *
                velocity[m][at(d)][at(f)];
  }
  return state_.porosity[at(momentum >= 0.0 ? lower : upper)];
}

// U_FC -= sign dt y grad dP for every material (sign -1 takes it back).
template <int Dim>
void IceSolver<Dim>::correct_face_velocities(double dt, double sign) {
  const CellField* increment = &pressure_increment_;
  if (sign != 1.0) {
    signed_increment_.resize(pressure_increment_.size());
    for (std::size_t c = 0; c < signed_increment_.size(); ++c)
      signed_increment_[c] = sign * pressure_increment_[c];
    increment = &signed_increment_;
  }
  for (std::size_t m = 0; m < count(); ++m) {
    for (int d = 0; d < Dim; ++d) {
      const std::vector<double>& y = face_correction_[m][at(d)];
      std::vector<double>& density = scratch_face_[at(d)];
      for (std::size_t f = 0; f < y.size(); ++f) density[f] = 1.0 / y[f];
    }
    pressure_solver_.correct_face_velocities(scratch_face_, *increment, dt, face_velocity_[m]);
  }
}

template <int Dim>
double IceSolver<Dim>::face_courant(double dt) const {
  double rate = 0.0;
  for (std::size_t m = 0; m < count(); ++m) {
    rate = std::max(rate, advection_rate(grid_, face_velocity_[m],
                                         link_ ? std::span<const unsigned char>(owned_)
                                               : std::span<const unsigned char>()));
  }
  return max_over_blocks(rate) * dt;
}

// Tran et al., MPMICE, eq. 54 with the mixture bulk densities
// rho_c = sum_f rhobar_f: each cell's pressure force balances its own
// weight at rest, across a water-air interface too. On a side without a
// fixed pressure the face takes the cell's pressure extrapolated
// hydrostatically (zero dynamic pressure gradient).
//
// Where the fluids drag on a solid (a = K / n^2 > 0 on either side) the
// face pressure instead balances each half cell by Darcy's law with the
// same superficial flux: the pressure rises hydrostatically from each
// centre and the rest of the difference drops in proportion to the halves'
// resistances,
//   P_FC = P_L + (dx/2) rho_L g + a_L / (a_L + a_R) (P_R - P_L - (dx/2)(rho_L + rho_R) g),
// rho the fluids' intrinsic density. At rest this is eq. 54's hydrostatic
// face pressure; at the inlet of a porous column it is the free fluid's
// pressure, as it should be (eq. 54 there would pull the free cell into
// the column with the column's first pressure drop).
template <int Dim>
void IceSolver<Dim>::compute_face_pressure() {
  CellField& rho = scratch_cell_;  // the mixture densities
  rho.assign(at(grid_.cell_count()), 0.0);
  for (const MaterialState<Dim>& material : state_.materials) {
    for (std::size_t c = 0; c < rho.size(); ++c) rho[c] += material.bulk_density[c];
  }
  const double* p = new_pressure_.data();
  for (int d = 0; d < Dim; ++d) {
    const double dx = grid_.spacing()[d];
    double* face_p = face_pressure_[at(d)].data();
    for_each_face(
        grid_, d,
        [&](int f, int lower, int upper) {
          const double rho_l = rho[at(lower)];
          const double rho_r = rho[at(upper)];
          if (solid_drag_on_) {
            const double n_l = state_.porosity[at(lower)];
            const double n_r = state_.porosity[at(upper)];
            const double a_l = solid_drag_[at(lower)] / (n_l * n_l);
            const double a_r = solid_drag_[at(upper)] / (n_r * n_r);
            if (a_l + a_r > 0.0) {
              const double rise_l = 0.5 * dx * rho_l / n_l * gravity_[d];
              const double rise_r = 0.5 * dx * rho_r / n_r * gravity_[d];
              face_p[f] =
                  p[lower] + rise_l + a_l / (a_l + a_r) * (p[upper] - p[lower] - rise_l - rise_r);
              return;
            }
          }
          face_p[f] = (p[lower] * rho_r + p[upper] * rho_l) / (rho_l + rho_r);
        },
        [&](int f, int cell, bool upper_side) {
          const SideCondition& side = sides_[at(2 * d + (upper_side ? 1 : 0))];
          if (side.type == SideType::fixed_pressure) {
            face_p[f] = side.pressure;
          } else {
            // The fluids' intrinsic density: in a porous cell their weight
            // rhobar g is carried by n grad P.
            const double offset = upper_side ? 0.5 * dx : -0.5 * dx;
            face_p[f] = p[cell] + rho[at(cell)] / state_.porosity[at(cell)] * gravity_[d] * offset;
          }
        });
  }
}

// The volume fraction of material m on a face, as the pressure equation
// took it (the upwind cell's).
template <int Dim>
double IceSolver<Dim>::face_fraction(std::size_t m, int d, int face) const {
  return face_fraction_[m][at(d)][at(face)];
}

template <int Dim>
void IceSolver<Dim>::compute_lagrangian_values(double dt) {
  for (std::size_t m = 0; m < count(); ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    const double* rhobar = material.bulk_density.data();
    const double* phi = material.volume_fraction.data();
    std::copy(material.bulk_density.begin(), material.bulk_density.end(), mass_[m].begin());
    for (int d = 0; d < Dim; ++d) {
      const double dx = grid_.spacing()[d];
      const double g = gravity_[d];
      const double* u = material.velocity[at(d)].data();
      double* momentum = momentum_[m][at(d)].data();
      for_each_row(grid_, [&](int first, int length) {
        // The cell's lower and upper faces normal to d.
        const double* p_low = face_pressure_[at(d)].data() + lower_face_offset(grid_, d, first);
        const double* p_up = p_low + grid_.stride(d);
        for (int c = first; c < first + length; ++c) {
          const double gradient = (p_up[c] - p_low[c]) / dx;
          momentum[c] = rhobar[c] * u[c] + dt * (-phi[c] * gradient + rhobar[c] * g);
        }
      });
    }
  }
}

// The internal energy of eqs. 60 and 63 with the work in the compatible form
// described above compute_lagrangian_values, U_mid taken after the momentum
// exchange (the velocity the material actually reaches: a trace material
// accelerated by the pressure and stopped by the drag does no work).
template <int Dim>
bool IceSolver<Dim>::compute_lagrangian_energy(double dt) {
  const std::size_t cells = at(grid_.cell_count());
  // Below this volume fraction a material is a trace (the initial state
  // gives absent materials 1e-6 by default).
  constexpr double trace_volume_fraction = 1e-5;
  std::array<double, cosim::exchange::kMaxMaterials> specific_heat{};
  for (std::size_t k = 0; k < count(); ++k) specific_heat[k] = eos_[k]->specific_heat();
  const auto cell_temperature = [&](std::size_t i) {
    double heat = 0.0, capacity = 0.0;
    for (std::size_t k = 0; k < count(); ++k) {
      const double c = state_.materials[k].bulk_density[i] * specific_heat[k];
      heat += c * state_.materials[k].temperature[i];
      capacity += c;
    }
    return heat / capacity;
  };
  bool empty = false;  // some owned cell left without internal energy
  for (std::size_t m = 0; m < count(); ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    const double c_v = eos_[m]->specific_heat();
    int refused = 0;
    for_each_row(grid_, [&](int first, int length) {
      LagrangianEnergyRow<Dim> row;
      for (int d = 0; d < Dim; ++d) {
        const int offset = lower_face_offset(grid_, d, first);
        row.face_pressure[at(d)] = face_pressure_[at(d)].data() + offset;
        row.face_fraction[at(d)] = face_fraction_[m][at(d)].data() + offset;
        row.face_velocity[at(d)] = face_velocity_[m][at(d)].data() + offset;
        row.stride[at(d)] = grid_.stride(d);
        row.spacing[at(d)] = grid_.spacing()[d];
        row.velocity[at(d)] = material.velocity[at(d)].data();
        row.momentum[at(d)] = momentum_[m][at(d)].data();
      }
      refused += lagrangian_energy_row(
          row, first, first + length, dt, c_v, material.bulk_density.data(),
          material.volume_fraction.data(), kappa_[m].data(), pressure_increment_.data(),
          new_pressure_.data(), material.temperature.data(), energy_[m].data());
    });
    // A trace of a material (a little air carried into wet soil) sits where
    // the pressure equation is the other materials': its share of the work
    // is not its own compression, and where the pores open and close (a
    // coupled solid) it heats or cools it step after step, by orders of
    // magnitude, to no energy at all (then to a negative temperature after
    // advection) or to a bubble. A trace more than a factor two off the
    // cell's temperature takes the cell's temperature instead (its energy is
    // a trace too).
    const double* phi = material.volume_fraction.data();
    double* energy = energy_[m].data();
    for (std::size_t i = 0; i < cells; ++i) {
      if (!(phi[i] < trace_volume_fraction)) continue;
      const double equilibrium = material.bulk_density[i] * c_v * cell_temperature(i);
      if (!(energy[i] > 0.5 * equilibrium && energy[i] < 2.0 * equilibrium))
        energy[i] = equilibrium;
    }
    // A compression too strong for the step (or work that empties a
    // material) leaves no internal energy: the step is refused.
    if (refused > 0) {
      for (std::size_t i = 0; i < cells && !empty; ++i) {
        empty = owned_[i] != 0 && (!(energy[i] > 0.0) || !std::isfinite(energy[i]));
      }
    }
    if (empty) break;
  }
  return !any_block(empty);
}

// Tran et al., MPMICE, eqs. 73-76 per unit volume: each material's share
// f_f = phi_f kappa_f / sum phi kappa of the volume change, plus its thermal
// expansion relative to the mixture's.
template <int Dim>
void IceSolver<Dim>::compute_lagrangian_specific_volume(double /*dt*/) {
  const std::size_t n = count();
  const std::size_t cells = at(grid_.cell_count());
  // Each material's thermal expansivity alpha_f(rho_f, T_f) per cell (kept
  // in volume_, which is written below) and their sum weighted by the
  // temperature change.
  CellField& thermal_mixture = scratch_cell_;
  thermal_mixture.assign(cells, 0.0);
  for (std::size_t m = 0; m < n; ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    double* alpha = volume_[m].data();
    visit_model_copy(*eos_[m], [&](const auto& eos) {  // inlined for the built-in models
      for (std::size_t c = 0; c < cells; ++c) {
        alpha[c] = eos.thermal_expansivity(material.density[c], material.temperature[c]);
        thermal_mixture[c] += material.volume_fraction[c] * alpha[c] *
                              (lagrangian_temperature_[m][c] - material.temperature[c]);
      }
    });
  }
  for (std::size_t m = 0; m < n; ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    for (std::size_t c = 0; c < cells; ++c) {
      const double phi = material.volume_fraction[c];
      const double alpha = volume_[m][c];
      const double share = phi * kappa_[m][c] / mixture_kappa_[c];
      volume_[m][c] = phi - phi * kappa_[m][c] * pressure_increment_[c] +
                      phi * alpha * (lagrangian_temperature_[m][c] - material.temperature[c]) -
                      share * thermal_mixture[c];
    }
  }
}

// Tran et al., MPMICE, eqs. 77-84: advection of the Lagrangian densities by
// the final face velocities, then the primitive variables and the pressure
// equilibrium of the new state.
template <int Dim>
void IceSolver<Dim>::advect_and_update(double dt, StepReport& report) {
  const std::size_t n = count();
  const std::size_t cells = at(grid_.cell_count());
  const auto dim = static_cast<std::size_t>(Dim);
  const auto kinetic_energy = [&](std::size_t m, std::size_t c) {
    double twice = 0.0;
    for (std::size_t d = 0; d < dim; ++d) twice += momentum_[m][d][c] * momentum_[m][d][c];
    return 0.5 * twice / mass_[m][c];
  };
  const bool total_energy = options_.conserve_total_energy;
  for (std::size_t m = 0; m < n; ++m) {
    std::array<std::span<double>, static_cast<std::size_t>(Dim) + 4> fields;
    fields[0] = mass_[m];
    for (std::size_t d = 0; d < dim; ++d) fields[1 + d] = momentum_[m][d];
    fields[dim + 1] = energy_[m];
    fields[dim + 2] = volume_[m];
    if (total_energy) {
      for (std::size_t c = 0; c < cells; ++c) kinetic_[m][c] = kinetic_energy(m, c);
      fields[dim + 3] = kinetic_[m];
    }
    advector_.advance(
        face_velocity_[m], dt,
        std::span<const std::span<double>>(fields.data(), total_energy ? dim + 4 : dim + 3),
        state_.porosity);
    // The kinetic energy the advection dissipated back into the internal
    // energy, then the primitive variables, in one pass; a bad cell is
    // reported by the checking pass below.
    MaterialState<Dim>& material = state_.materials[m];
    const double c_v = eos_[m]->specific_heat();
    std::array<const double*, static_cast<std::size_t>(Dim)> momentum{};
    for (std::size_t d = 0; d < dim; ++d) momentum[d] = momentum_[m][d].data();
    std::array<double*, static_cast<std::size_t>(Dim)> velocity{};
    for (std::size_t d = 0; d < dim; ++d) velocity[d] = material.velocity[d].data();
    const auto primitives =
        total_energy ? primitive_variables<Dim, true> : primitive_variables<Dim, false>;
    const bool bad = primitives(cells, c_v, momentum, velocity, mass_[m].data(), kinetic_[m].data(),
                                volume_[m].data(), energy_[m].data(), material.bulk_density.data(),
                                material.temperature.data(), material.specific_volume.data()) > 0;
    if (!bad) continue;
    for (std::size_t c = 0; c < cells; ++c) {
      if (owned_[c] == 0) continue;  // a ghost's own step is the owner's to judge
      const double mass = mass_[m][c];
      if (!(mass > 0.0) || !std::isfinite(mass)) {
        throw cosim::NumericalError(
            fmt::format("ICE: material '{}' in cell {}: bulk density {} kg/m3 after advection "
                        "(time {} s, dt {} s)",
                        materials_[m].name, c, mass, time_, dt));
      }
      if (!(material.temperature[c] > 0.0) || !std::isfinite(material.temperature[c])) {
        throw cosim::NumericalError(fmt::format(
            "ICE: material '{}' in cell {}: temperature {} K after advection (time {} s, dt {} s)",
            materials_[m].name, c, material.temperature[c], time_, dt));
      }
    }
  }
  double closure = 0.0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (owned_[c] == 0) continue;
    double volume = 0.0;
    for (std::size_t m = 0; m < n; ++m) volume += volume_[m][c];
    closure = std::max(closure, std::abs(volume - state_.porosity[c]));
  }
  report.volume_closure = closure;
  move_solid(dt);
  state_.pressure = new_pressure_;
  equilibrate(&report);
  for (std::size_t m = 0; m < n; ++m) {
    MaterialState<Dim>& material = state_.materials[m];
    for (std::size_t c = 0; c < cells; ++c) material.specific_volume[c] = 1.0 / material.density[c];
  }
}

// The pores follow the solid within a step: its volume is conserved
// (incompressible grains), so n_c changes by dt div(phi_s,FC U_s,FC) with the
// same face fluxes the pressure equation's divergence took (Tran et al.,
// MPMICE, eq. 107 in conservative form), plus what set_porous_medium(displace)
// left, which the pressure equation took as its source. Without a solid
// nothing changes.
template <int Dim>
void IceSolver<Dim>::move_solid(double dt) {
  bool solid = !porosity_to_displace_.empty();
  for (const double n : state_.porosity) solid = solid || n < 1.0;
  if (!solid) return;
  std::vector<double>& change = porosity_change_;
  if (porosity_to_displace_.empty()) {
    change.assign(at(grid_.cell_count()), 0.0);
  } else {
    change.swap(porosity_to_displace_);
    porosity_to_displace_.clear();
  }
  for (int d = 0; d < Dim; ++d) {
    const double factor = dt / grid_.spacing()[d];
    const std::vector<double>& u = solid_face_velocity_[at(d)];
    const std::vector<double>& phi = solid_face_fraction_[at(d)];
    for (int f = 0; f < grid_.face_count(d); ++f) {
      const double flux = factor * phi[at(f)] * u[at(f)];
      if (flux == 0.0) continue;
      const int lower = grid_.lower_cell(d, f);
      const int upper = grid_.upper_cell(d, f);
      if (lower >= 0) change[at(lower)] += flux;
      if (upper >= 0) change[at(upper)] -= flux;
    }
  }
  for (std::size_t c = 0; c < change.size(); ++c) {
    state_.porosity[c] = std::clamp(state_.porosity[c] + change[c], 1e-3, 1.0);
  }
}

// Newtonian stress (molecular plus Smagorinsky's eddy viscosity) of each
// material from its own velocity, as conservative face fluxes.
template <int Dim>
void IceSolver<Dim>::add_viscous_stress(double dt) {
  for (std::size_t m = 0; m < count(); ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    if (options_.smagorinsky_constant > 0.0) {
      viscosity_.resize(material.density.size());
      smagorinsky_viscosity(grid_, material.velocity, material.density,
                            options_.smagorinsky_constant, std::span<double>(viscosity_));
      for (double& mu : viscosity_) mu += materials_[m].viscosity;
    } else {
      if (materials_[m].viscosity == 0.0) continue;
      viscosity_.assign(material.density.size(), materials_[m].viscosity);
    }
    diffusion_.add_viscous_momentum(viscosity_, material.volume_fraction, material.velocity, dt,
                                    momentum_[m]);
  }
}

// Conduction of each material's heat, per unit volume (energy_ holds
// rhobar c_v T).
template <int Dim>
void IceSolver<Dim>::add_heat_conduction(double dt) {
  for (std::size_t m = 0; m < count(); ++m) {
    if (materials_[m].thermal_conductivity == 0.0) continue;
    const MaterialState<Dim>& material = state_.materials[m];
    viscosity_.assign(material.density.size(), materials_[m].thermal_conductivity);
    diffusion_.add_heat_conduction(viscosity_, material.volume_fraction, material.temperature, dt,
                                   energy_[m]);
  }
}

template <int Dim>
std::vector<MaterialTotals> IceSolver<Dim>::totals() const {
  std::vector<MaterialTotals> result(count());
  const double volume = grid_.cell_volume();
  for (std::size_t m = 0; m < count(); ++m) {
    const MaterialState<Dim>& material = state_.materials[m];
    const double c_v = eos_[m]->specific_heat();
    for (std::size_t c = 0; c < material.bulk_density.size(); ++c) {
      if (owned_[c] == 0) continue;
      const double mass = material.bulk_density[c] * volume;
      result[m].mass += mass;
      for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
        result[m].momentum[d] += mass * material.velocity[d][c];
        result[m].kinetic_energy += 0.5 * mass * material.velocity[d][c] * material.velocity[d][c];
      }
      result[m].internal_energy += mass * c_v * material.temperature[c];
    }
  }
  if (link_) {
    std::vector<double> sums;
    for (const MaterialTotals& t : result) {
      sums.insert(sums.end(), {t.mass, t.momentum[0], t.momentum[1], t.momentum[2],
                               t.internal_energy, t.kinetic_energy});
    }
    link_->sum(sums);
    for (std::size_t m = 0; m < count(); ++m) {
      const double* t = sums.data() + 6 * m;
      result[m] = {t[0], {t[1], t[2], t[3]}, t[4], t[5]};
    }
  }
  return result;
}

template <int Dim>
typename PressureSolver<Dim>::Boundaries IceSolver<Dim>::pressure_boundaries(const Sides& sides) {
  typename PressureSolver<Dim>::Boundaries boundaries{};
  for (std::size_t s = 0; s < sides.size(); ++s) {
    boundaries[s] = sides[s].type == SideType::fixed_pressure ? PressureBoundary::fixed_pressure
                                                              : PressureBoundary::wall;
  }
  return boundaries;
}

template <int Dim>
void IceSolver<Dim>::use_pressure_solver(std::unique_ptr<PressureSystemSolver<Dim>> pressure) {
  pressure_system_ = std::move(pressure);
}

template <int Dim>
void IceSolver<Dim>::link_blocks(std::shared_ptr<BlockLink<Dim>> link,
                                 std::unique_ptr<PressureSystemSolver<Dim>> pressure) {
  require(link != nullptr && pressure != nullptr,
          "a linked block needs its link and pressure solver");
  const auto owned = link->owned_cells();
  for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
    require(owned[d][0] >= 0 && owned[d][0] < owned[d][1] && owned[d][1] <= grid_.cells()[d],
            "the owned cells must lie in the block's grid");
  }
  for (int c = 0; c < grid_.cell_count(); ++c) {
    const auto ijk = grid_.cell_ijk(c);
    bool inside = true;
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d)
      inside = inside && ijk[d] >= owned[d][0] && ijk[d] < owned[d][1];
    owned_[at(c)] = inside ? 1 : 0;
  }
  link_ = std::move(link);
  pressure_system_ = std::move(pressure);
}

template <int Dim>
bool IceSolver<Dim>::any_block(bool local) const {
  return link_ ? link_->max(local ? 1.0 : 0.0) > 0.0 : local;
}

template <int Dim>
double IceSolver<Dim>::max_over_blocks(double local) const {
  return link_ ? link_->max(local) : local;
}

// Everything SavedIceState lists as cell fields, as their owners hold them.
template <int Dim>
void IceSolver<Dim>::refresh_ghosts() {
  std::vector<std::span<double>> fields{state_.pressure, state_.porosity, mixture_kappa_};
  for (auto& component : state_.solid_velocity) fields.emplace_back(component);
  for (std::size_t m = 0; m < count(); ++m) {
    MaterialState<Dim>& material = state_.materials[m];
    fields.insert(fields.end(), {material.bulk_density, material.temperature, material.density,
                                 material.volume_fraction, material.specific_volume, kappa_[m]});
    for (auto& component : material.velocity) fields.emplace_back(component);
  }
  link_->fill_ghosts(fields);
}

template class IceSolver<1>;
template class IceSolver<2>;
template class IceSolver<3>;

}  // namespace ice

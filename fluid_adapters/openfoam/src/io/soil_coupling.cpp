#include "openfoam/io/soil_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "cosim/error.hpp"
#include "cosim/fields.hpp"
#include "openfoam/cloud/ergun_wen_yu.hpp"

namespace openfoam {

namespace {

namespace f = cosim::fields;
// mpm_solver marks a held (rigid) body's bulk density above this [kg/m^3].
constexpr double held_solid_bulk_density = 1e20;

cosim::FieldSpec field(const f::Field& field, int dimension, double lower = -INFINITY,
                       double upper = INFINITY) {
  cosim::FieldSpec spec = field.on(SoilCoupling::mesh_name, dimension);
  spec.lower_bound = lower;
  spec.upper_bound = upper;
  return spec;
}

}  // namespace

SoilCoupling::SoilCoupling(const CaseDescription& description, const CaseMesh& mesh,
                           const CaseProperties& properties, CellNeighbours neighbours)
    : c_(description),
      mesh_(mesh),
      properties_(properties),
      neighbours_(std::move(neighbours)),
      water_(properties.water),
      air_(properties.air),
      dim_(mesh.mesh.dimension()) {}

double SoilCoupling::plane_volume(std::size_t c) const {
  return properties_.declared_volume(mesh_.volumes[c]);
}

void SoilCoupling::declare(cosim::Participant& participant) const {
  participant.declare_mesh(mesh_.mesh);
  participant.declare_read(field(f::solid_fraction, dim_, 0.0, 1.0), 0.0);
  participant.declare_read(field(f::solid_velocity, dim_), 0.0);
  participant.declare_read(field(f::drag_coefficient, dim_, 0.0), 0.0);
  participant.declare_read(field(f::solid_bulk_density, dim_, 0.0), 0.0);
  cosim::FieldSpec flux = field(f::solid_volume_flux, dim_);
  flux.optional = true;
  participant.declare_read(flux, 0.0);
  participant.declare_write(field(f::pore_pressure, dim_));
  participant.declare_write(field(f::fluid_velocity, dim_));
  participant.declare_write(field(f::fluid_bulk_density, dim_, 0.0));
  participant.declare_write(field(f::water_fraction, dim_, 0.0, 1.0));
  participant.declare_write(field(f::momentum_exchange_impulse, dim_));
}

void SoilCoupling::read_soil(const cosim::Participant& participant) {
  const std::size_t cells = mesh_.volumes.size();
  solid_fraction_.resize(cells);
  solid_velocity_.resize(cells * static_cast<std::size_t>(dim_));
  drag_.resize(cells);
  // OpenFOAM runs the window on one soil: when the fields vary within the
  // window (time_interpolation: linear), their window mean, the values at
  // its middle.
  const double at =
      participant.reads_vary_within_window() ? 0.5 * participant.max_time_step() : 0.0;
  participant.read(f::solid_fraction.name, solid_fraction_, at);
  participant.read(f::solid_velocity.name, solid_velocity_, at);
  participant.read(f::drag_coefficient.name, drag_, at);
  solid_density_.resize(cells);
  participant.read(f::solid_bulk_density.name, solid_density_, at);
  const auto dim = static_cast<std::size_t>(dim_);
  volume_flux_.resize(cells * dim);
  if (participant.is_sent(f::solid_volume_flux.name)) {
    participant.read(f::solid_volume_flux.name, volume_flux_, at);
  } else {
    for (std::size_t c = 0; c < cells; ++c) {
      const double phi_s = 1.0 - pore_fraction(c);
      for (std::size_t k = 0; k < dim; ++k)
        volume_flux_[c * dim + k] = phi_s * solid_velocity_[c * dim + k];
    }
  }
}

std::vector<double> SoilCoupling::fluid_fraction(const cosim::Participant& participant) {
  read_soil(participant);
  std::vector<double> n(mesh_.volumes.size());
  for (std::size_t c = 0; c < n.size(); ++c) n[c] = pore_fraction(c);
  return n;
}

double SoilCoupling::pore_fraction(std::size_t c) const {
  const double phi_s = std::min(solid_fraction_[c], c_.soil.max_solid_fraction);
  return std::max(1.0 - phi_s, 1.0 - c_.soil.max_solid_fraction);
}

const std::vector<double>& SoilCoupling::darcy_coefficients(const cosim::Participant& participant) {
  read_soil(participant);
  const std::size_t cells = mesh_.volumes.size();
  darcy_.assign(cells, 0.0);
  for (std::size_t c = 0; c < cells; ++c) {
    if (solid_fraction_[c] < c_.soil.minimum_solid_fraction || !(drag_[c] > 0.0)) continue;
    const double n = pore_fraction(c);
    // The job's law is the water's: OpenFOAM scales d by the cell's own mu.
    darcy_[c] = drag_[c] / (n * n * water_.viscosity);
  }
  return darcy_;
}

const SoilParcels& SoilCoupling::parcels(const cosim::Participant& participant,
                                         const FoamFields& start) {
  const std::size_t cells = mesh_.volumes.size();
  const auto dim = static_cast<std::size_t>(dim_);
  read_soil(participant);
  diameter_.assign(cells, 0.0);
  parcels_.clear();
  const SoilSettings& soil = c_.soil;
  const double smallest_pore = 1.0 - soil.max_solid_fraction;
  for (std::size_t c = 0; c < cells; ++c) {
    const double phi_s = std::min(solid_fraction_[c], soil.max_solid_fraction);
    if (phi_s < soil.minimum_solid_fraction || !(drag_[c] > 0.0)) continue;
    const double n = std::max(1.0 - phi_s, smallest_pore);
    double relative[3] = {0.0, 0.0, 0.0};
    double speed2 = 0.0;
    for (std::size_t d = 0; d < dim; ++d) {
      const double u_f =
          fluid_velocity_.empty() ? start.velocity[c * dim + d] : fluid_velocity_[c * dim + d];
      relative[d] = u_f - solid_velocity_[c * dim + d];
      speed2 += relative[d] * relative[d];
    }
    // The job's law is the water's (K = n^2 mu_w / k): the grain solved with
    // the water's density and viscosity gives the soil's permeability, and
    // OpenFOAM's drag then follows the cell's own fluid (air drags mu_a / mu_w
    // as much).
    const CloudDragInput input{phi_s, water_.density, water_.viscosity, std::sqrt(speed2)};
    const double d = ergun_wen_yu_grain_size_within_range(input, drag_[c] / n);
    diameter_[c] = d;
    // With the displaced water the solver's water moves at u_f + F / n (F the
    // solids' volume flux): the parcels at U_s + F / n keep the drag's U_s - u_f.
    double u[3] = {0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < dim; ++k) {
      u[k] = solid_velocity_[c * dim + k] +
             (soil.displaced_water ? volume_flux_[c * dim + k] / n : 0.0);
    }
    const double grain_volume = std::numbers::pi * d * d * d / 6.0;
    // A hair off the cell's centre: a parcel starting exactly there (the apex
    // of all the cell's tets) can stall OpenFOAM v1912's tracking for good.
    const double size = dim_ == 2 ? std::sqrt(plane_volume(c)) : std::cbrt(mesh_.volumes[c]);
    const double offset[3] = {3.1e-4 * size, 1.7e-4 * size, dim_ == 3 ? 1.1e-4 * size : 0.0};
    double position[3];
    for (std::size_t k = 0; k < 3; ++k) position[k] = mesh_.centres[3 * c + k] + offset[k];
    parcels_.add(position, static_cast<std::int64_t>(c), u, d,
                 phi_s * mesh_.volumes[c] / grain_volume);
  }
  return parcels_;
}

SoilCoupling::MomentumCheck SoilCoupling::write(cosim::Participant& participant, FoamFields& end,
                                                double window, long steps) {
  const std::size_t cells = mesh_.volumes.size();
  const auto dim = static_cast<std::size_t>(dim_);
  if (porosity_zones()) return write_porosity_zones(participant, end, window);
  if (c_.soil.displaced_water) {
    for (std::size_t c = 0; c < cells; ++c) {
      if (diameter_.empty() || diameter_[c] <= 0.0) continue;
      const double n = pore_fraction(c);
      for (std::size_t d = 0; d < dim; ++d)
        end.velocity[c * dim + d] -= volume_flux_[c * dim + d] / n;
    }
  }
  fluid_velocity_ = end.velocity;
  std::vector<double> impulse_rate(cells * dim, 0.0);
  MomentumCheck check;
  double cloud[3] = {0, 0, 0}, law[3] = {0, 0, 0}, soil[3] = {0, 0, 0}, scale = 0.0, off = 0.0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (diameter_.empty() || diameter_[c] <= 0.0) continue;
    const double n = pore_fraction(c);
    const double phi_s = 1.0 - n;
    double speed2 = 0.0;
    for (std::size_t d = 0; d < dim; ++d) {
      const double r = end.velocity[c * dim + d] - solid_velocity_[c * dim + d];
      speed2 += r * r;
    }
    const CloudDragInput input{phi_s, mixture_density(end, c, water_, air_),
                               mixture_viscosity(end, c, water_, air_), std::sqrt(speed2)};
    const double k_cloud = ergun_wen_yu_coefficient(input, diameter_[c]);
    const double volume = plane_volume(c);
    // An impermeable solid (a rigid bed: solid fraction at the cap) holds its
    // pores' trace of water at its own velocity. Its law (K ~ 1e15) would turn
    // the water's leftover velocity into kicks on grains that share the cell,
    // so it exchanges nothing with the soil, and is not compared.
    if (solid_fraction_[c] >= c_.soil.max_solid_fraction) continue;
    // A held solid (a rigid body: the MPM marks its bulk density) absorbs
    // what it receives; grains sharing its cells would take a volume share
    // of its drag, so the cell gives the soil nothing.
    const bool held = solid_density_[c] > held_solid_bulk_density;
    // The exchange is explicit: over a window the drag cannot give the soil
    // more than brings it to the water's velocity (beta T <= 1, beta =
    // n K_cloud / rho_bar_s); beyond, it would overshoot and diverge (seen
    // in cells the grains share with a rigid bed).
    const double beta_window =
        solid_density_[c] > 0.0 ? n * k_cloud * window / solid_density_[c] : 0.0;
    const double limiter = held ? 0.0 : 1.0 / std::max(1.0, beta_window);
    if (!held && beta_window > 1.0) {
      ++check.limited_cells;
      check.shortest_relaxation = std::min(check.shortest_relaxation, window / beta_window);
    }
    for (std::size_t d = 0; d < dim; ++d) {
      const double relative = end.velocity[c * dim + d] - solid_velocity_[c * dim + d];
      const double on_fluid = -k_cloud * relative * volume * window;
      double reaction = on_fluid;
      law[d] += on_fluid;
      scale += std::abs(on_fluid);
      if (!end.cloud_momentum.empty()) {
        const double measured = end.cloud_momentum[c * dim + d] * static_cast<double>(steps) *
                                volume / mesh_.volumes[c];
        cloud[d] += measured;
        off += std::abs(measured - on_fluid);
        // The soil takes the reaction to what the water received, so that the
        // momentum lost by one is the other's (the law at the window's end
        // fields differs from it while the flow changes within the window;
        // its mismatch is the check of the grain size's fit).
        reaction = measured;
      }
      impulse_rate[c * dim + d] = -n * limiter * reaction / window;
      soil[d] += -n * reaction;
    }
  }
  for (std::size_t d = 0; d < dim; ++d) {
    check.cloud_on_fluid += cloud[d] * cloud[d];
    check.law_on_fluid += law[d] * law[d];
    check.to_soil += soil[d] * soil[d];
  }
  check.cloud_on_fluid = std::sqrt(check.cloud_on_fluid);
  check.law_on_fluid = std::sqrt(check.law_on_fluid);
  check.to_soil = std::sqrt(check.to_soil);
  check.mismatch = scale > 0.0 ? off / scale : 0.0;
  extend_pressure_into_impermeable_cells(end.p);
  write_fields(participant, end, end.alphac, impulse_rate);
  return check;
}

SoilCoupling::MomentumCheck SoilCoupling::write_porosity_zones(cosim::Participant& participant,
                                                               FoamFields& end, double window) {
  const std::size_t cells = mesh_.volumes.size();
  const auto dim = static_cast<std::size_t>(dim_);
  // interFoam's U is superficial: the pore water moves at U / n.
  std::vector<double> fluid_fraction(cells, 1.0), impulse_rate(cells * dim, 0.0);
  MomentumCheck check;
  double law[3] = {0, 0, 0};
  for (std::size_t c = 0; c < cells; ++c) {
    if (darcy_.empty() || darcy_[c] <= 0.0) continue;
    const double n = pore_fraction(c);
    fluid_fraction[c] = n;
    const double mu_d = mixture_viscosity(end, c, water_, air_) * darcy_[c];
    for (std::size_t d = 0; d < dim; ++d) {
      const double on_fluid = -mu_d * end.velocity[c * dim + d] * plane_volume(c) * window;
      law[d] += on_fluid;
      impulse_rate[c * dim + d] = -n * on_fluid / window;
      end.velocity[c * dim + d] /= n;
    }
  }
  for (std::size_t d = 0; d < dim; ++d) check.law_on_fluid += law[d] * law[d];
  check.law_on_fluid = std::sqrt(check.law_on_fluid);
  check.to_soil =
      check.law_on_fluid;  // times n per cell; the soil's own -phi_s grad p does the rest
  fluid_velocity_ = end.velocity;
  write_fields(participant, end, fluid_fraction, impulse_rate);
  return check;
}

void SoilCoupling::extend_pressure_into_impermeable_cells(std::vector<double>& p) const {
  // OpenFOAM's pressure in the trace of pores of an impermeable solid means
  // nothing (its water is locked by a drag of ~1e17), yet it reaches the
  // soil's points beside the solid through the pressure gradient: it is
  // replaced, front by front, by the mean of its cells' permeable (or
  // already replaced) face neighbours.
  if (solid_fraction_.empty()) return;
  const std::size_t cells = p.size();
  std::vector<char> known(cells);
  for (std::size_t c = 0; c < cells; ++c)
    known[c] = solid_fraction_[c] < c_.soil.max_solid_fraction ? 1 : 0;
  std::vector<std::size_t> front;
  for (bool changed = true; changed;) {
    front.clear();
    for (std::size_t c = 0; c < cells; ++c) {
      if (known[c]) continue;
      double sum = 0.0;
      int count = 0;
      for (std::size_t neighbour : neighbours_.of(c)) {
        if (known[neighbour] == 1) {
          sum += p[neighbour];
          ++count;
        }
      }
      if (count > 0) {
        p[c] = sum / count;
        front.push_back(c);
      }
    }
    for (std::size_t c : front) known[c] = 1;
    changed = !front.empty();
  }
}

void SoilCoupling::write_fields(cosim::Participant& participant, const FoamFields& end,
                                const std::vector<double>& fluid_fraction,
                                const std::vector<double>& impulse_rate) const {
  const std::size_t cells = mesh_.volumes.size();
  std::vector<double> density(cells), water(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    const double n = fluid_fraction.empty() ? 1.0 : fluid_fraction[c];
    density[c] = n * mixture_density(end, c, water_, air_);
    water[c] = std::clamp(n * end.alpha_water[c], 0.0, 1.0);
  }
  participant.write(f::pore_pressure.name, end.p);
  participant.write(f::fluid_velocity.name, end.velocity);
  participant.write(f::fluid_bulk_density.name, density);
  participant.write(f::water_fraction.name, water);
  participant.write(f::momentum_exchange_impulse.name, impulse_rate);
}

}  // namespace openfoam

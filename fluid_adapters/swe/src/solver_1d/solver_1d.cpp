#include "swe/solver_1d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosim/error.hpp"
#include "solver_1d/flux_stage.hpp"
#include "solver_1d/ghost_cells.hpp"
#include "solver_1d/line_cells.hpp"
#include "swe/numerics/manning_friction.hpp"

namespace swe {

using solver_1d::ghost_layers;

namespace {

constexpr std::size_t parallel_cells = 8192;

void check_physics(const Physics& p) {
  if (!(p.gravity > 0.0) || !std::isfinite(p.gravity)) {
    throw cosim::InputError(fmt::format("Solver1d: gravity must be positive, got {}", p.gravity));
  }
  if (!(p.manning >= 0.0) || !std::isfinite(p.manning)) {
    throw cosim::InputError(
        fmt::format("Solver1d: Manning coefficient must be >= 0, got {}", p.manning));
  }
  if (!(p.dry_depth >= 0.0) || !std::isfinite(p.dry_depth)) {
    throw cosim::InputError(fmt::format("Solver1d: dry_depth must be >= 0, got {}", p.dry_depth));
  }
}

void check_scheme(const Scheme& s) {
  if (!(s.courant > 0.0 && s.courant <= 1.0)) {
    throw cosim::InputError(
        fmt::format("Solver1d: Courant number must lie in (0, 1], got {}", s.courant));
  }
}

void check_size(std::span<const double> values, std::size_t n, const char* what) {
  if (values.size() != n) {
    throw cosim::InputError(
        fmt::format("Solver1d: {} has {} values for {} cells", what, values.size(), n));
  }
}

}  // namespace

struct Solver1d::Impl {
  std::vector<double> edges;
  Physics physics;
  Scheme scheme;
  Boundaries1d boundaries;
  solver_1d::LineCells cells;
  // Cell values with two ghosts per side (cell i at i + 2). The ghosts of
  // h and q always hold the boundary values of the current state.
  std::vector<double> h, q, bed;
  std::vector<double> h_stage, q_stage;  // the first SSP-RK2 stage
  solver_1d::ImposedMassFlux imposed;
  std::vector<solver_1d::StageScratch> scratch;
  // save_state(): h, q and bed with their ghosts (the stage arrays and the
  // scratch are rewritten by every step before they are read).
  std::vector<double> saved_h, saved_q, saved_bed;
  bool has_saved_state = false;

  std::size_t n() const { return cells.count; }
  void fill_ghosts(std::vector<double>& depth, std::vector<double>& discharge) const {
    solver_1d::fill_ghost_cells(boundaries, physics, n(), depth.data(), discharge.data());
  }
  void apply_friction(double dt);
};

Solver1d::Solver1d(std::vector<double> edges, Physics physics, Scheme scheme,
                   Boundaries1d boundaries)
    : impl_(std::make_unique<Impl>()) {
  check_physics(physics);
  check_scheme(scheme);
  solver_1d::check_boundaries(boundaries);
  Impl& s = *impl_;
  s.cells = solver_1d::make_line_cells(edges);
  s.edges = std::move(edges);
  s.physics = physics;
  s.scheme = scheme;
  s.boundaries = boundaries;
  s.imposed.left = boundaries.left.kind == BoundaryKind::inflow_discharge;
  s.imposed.left_value = boundaries.left.value;
  s.imposed.right = boundaries.right.kind == BoundaryKind::inflow_discharge;
  s.imposed.right_value = -boundaries.right.value;
  const std::size_t size = s.n() + 2 * ghost_layers;
  s.h.assign(size, 0.0);
  s.q.assign(size, 0.0);
  s.bed.assign(size, 0.0);
  s.h_stage.assign(size, 0.0);
  s.q_stage.assign(size, 0.0);
  s.fill_ghosts(s.h, s.q);
}

Solver1d::~Solver1d() = default;

std::size_t Solver1d::cell_count() const {
  return impl_->n();
}

cosim::MeshGeometry Solver1d::cells() const {
  return cosim::NonUniformLine{impl_->edges};
}

double Solver1d::cell_size(std::size_t cell) const {
  return impl_->edges.at(cell + 1) - impl_->edges.at(cell);
}

std::size_t Solver1d::cell_at(double x, double /*y*/) const {
  const std::vector<double>& e = impl_->edges;
  if (!(x >= e.front() && x <= e.back())) return impl_->n();
  const auto above = std::upper_bound(e.begin(), e.end(), x);
  const auto cell = static_cast<std::size_t>(above - e.begin()) - 1;
  return std::min(cell, impl_->n() - 1);
}

void Solver1d::set_state(std::span<const double> h, std::span<const double> hu,
                         std::span<const double> /*hv*/) {
  Impl& s = *impl_;
  const std::size_t n = s.n();
  check_size(h, n, "depth");
  check_size(hu, n, "discharge");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(h[i] >= 0.0) || !std::isfinite(h[i])) {
      throw cosim::InputError(
          fmt::format("Solver1d: depth of cell {} must be finite and >= 0, got {}", i, h[i]));
    }
    if (!std::isfinite(hu[i])) {
      throw cosim::InputError(
          fmt::format("Solver1d: discharge of cell {} is not finite ({})", i, hu[i]));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    s.h[i + ghost_layers] = h[i];
    s.q[i + ghost_layers] = h[i] >= s.physics.dry_depth ? hu[i] : 0.0;
  }
  s.fill_ghosts(s.h, s.q);
}

void Solver1d::set_bed(std::span<const double> bed) {
  Impl& s = *impl_;
  check_size(bed, s.n(), "bed");
  for (std::size_t i = 0; i < bed.size(); ++i) {
    if (!std::isfinite(bed[i])) {
      throw cosim::InputError(
          fmt::format("Solver1d: bed of cell {} is not finite ({})", i, bed[i]));
    }
  }
  std::copy(bed.begin(), bed.end(), s.bed.begin() + ghost_layers);
  solver_1d::fill_ghost_bed(s.n(), s.bed.data());
}

double Solver1d::stable_time_step() const {
  const Impl& s = *impl_;
  const double g = s.physics.gravity, dry = s.physics.dry_depth;
  const double* h = s.h.data();
  const double* q = s.q.data();
  const double* inv_face_width = s.cells.inv_face_width.data();
  const auto faces = static_cast<std::ptrdiff_t>(s.n() + 1);
  const double sqrt_g = std::sqrt(g);
  double max_rate = 0.0;  // max over faces of speed / width
  // Branch-free (selects of doubles) so that the loop vectorises; a face
  // without water on either side adds rate 0.
#pragma omp parallel for simd schedule(static) reduction(max \
                                                         : max_rate) if (s.n() >= parallel_cells)
  for (std::ptrdiff_t f = 0; f < faces; ++f) {
    const auto l = static_cast<std::size_t>(f) + 1, r = l + 1;
    const double hl = h[l], hr = h[r];
    const double sql = std::sqrt(hl), sqr = std::sqrt(hr);
    const double velocity_l = q[l] / hl, velocity_r = q[r] / hr;
    const double ul = hl >= dry ? velocity_l : 0.0, ur = hr >= dry ? velocity_r : 0.0;
    // A wet cell next to a dry one launches a front at |u| + 2c.
    const double cl = sqrt_g * sql * (hr >= dry ? 1.0 : 2.0);
    const double cr = sqrt_g * sqr * (hl >= dry ? 1.0 : 2.0);
    const double side_speed = std::max(std::abs(ul) + cl, std::abs(ur) + cr);
    const double u_roe = (sql * ul + sqr * ur) / (sql + sqr);
    const double c_roe = std::sqrt(0.5 * g * (hl + hr));
    const double roe_speed = std::max(side_speed, std::abs(u_roe) + c_roe);
    const double speed = hl > 0.0 ? (hr > 0.0 ? roe_speed : side_speed) : side_speed;
    const double rate = speed * inv_face_width[f];
    max_rate = std::max(max_rate, hl <= 0.0 ? (hr <= 0.0 ? 0.0 : rate) : rate);
  }
  if (max_rate <= 0.0) return std::numeric_limits<double>::infinity();
  return s.scheme.courant / max_rate;
}

void Solver1d::Impl::apply_friction(double dt) {
  // Zheng et al., eq. 36, after the flux and bed-source step (eqs. 25-26).
  const double g = physics.gravity, manning = physics.manning, dry = physics.dry_depth;
  const auto count = static_cast<std::ptrdiff_t>(n());
  double* hp = h.data() + ghost_layers;
  double* qp = q.data() + ghost_layers;
#pragma omp parallel for schedule(static) if (n() >= parallel_cells)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    if (hp[i] < dry) continue;
    qp[i] *= manning_factor(hp[i], std::abs(qp[i] / hp[i]), g, manning, dt);
  }
}

void Solver1d::step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) {
    throw cosim::InputError(
        fmt::format("Solver1d::step: dt must be positive and finite, got {}", dt));
  }
  Impl& s = *impl_;
  solver_1d::advance_step(
      s.cells, s.physics, s.scheme, s.boundaries,
      {s.h.data(), s.q.data(), s.bed.data(), s.h_stage.data(), s.q_stage.data()}, s.imposed, dt,
      s.scratch);
  if (s.physics.manning > 0.0) s.apply_friction(dt);
  s.fill_ghosts(s.h, s.q);
}

void Solver1d::save_state() {
  Impl& s = *impl_;
  s.saved_h = s.h;
  s.saved_q = s.q;
  s.saved_bed = s.bed;
  s.has_saved_state = true;
}

void Solver1d::restore_state() {
  Impl& s = *impl_;
  if (!s.has_saved_state)
    throw cosim::Error(cosim::ExitCode::internal_error, "Solver1d: no saved state to restore");
  s.h = s.saved_h;
  s.q = s.saved_q;
  s.bed = s.saved_bed;
}

void Solver1d::write_state(cosim::StateFileWriter& out) const {
  const Impl& s = *impl_;
  out.numbers("h", s.h);
  out.numbers("q", s.q);
  out.numbers("bed", s.bed);
}

void Solver1d::read_state(const cosim::StateFileReader& in) {
  Impl& s = *impl_;
  in.numbers("h", s.h.size(), s.h);
  in.numbers("q", s.q.size(), s.q);
  in.numbers("bed", s.bed.size(), s.bed);
}

std::span<const double> Solver1d::depth() const {
  return std::span<const double>(impl_->h).subspan(ghost_layers, impl_->n());
}

std::span<const double> Solver1d::discharge_x() const {
  return std::span<const double>(impl_->q).subspan(ghost_layers, impl_->n());
}

std::span<const double> Solver1d::bed() const {
  return std::span<const double>(impl_->bed).subspan(ghost_layers, impl_->n());
}

Totals Solver1d::totals() const {
  const Impl& s = *impl_;
  Totals t;
  for (std::size_t i = 0; i < s.n(); ++i) {
    const double width = s.edges[i + 1] - s.edges[i];
    t.volume += s.h[i + ghost_layers] * width;
    t.momentum_x += s.q[i + ghost_layers] * width;
  }
  return t;
}

const Physics& Solver1d::physics() const {
  return impl_->physics;
}
const Scheme& Solver1d::scheme() const {
  return impl_->scheme;
}
const std::vector<double>& Solver1d::edges() const {
  return impl_->edges;
}

}  // namespace swe

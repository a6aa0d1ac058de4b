#include "swe/solver_2d.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cosim/decomposition/block_join.hpp"
#include "cosim/error.hpp"
#include "solver_2d/ghost_cells.hpp"
#include "solver_2d/padded_fields.hpp"
#include "solver_2d/row_loop.hpp"
#include "solver_2d/runge_kutta_stage.hpp"

namespace swe {

using solver_2d::PaddedFields;
using solver_2d::PaddedLayout;

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw cosim::InputError("swe 2D solver: " + what);
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// max over the row's cells of (|u| + k c) / dx + (|v| + k c) / dy (see
// stable_time_step); h, u, v address the row's first cell, `stride` is the
// row stride.
SWE_2D_ROW_LOOP double max_wave_rate(const double* h, const double* u, const double* v,
                                     std::ptrdiff_t nx, std::ptrdiff_t stride, double inv_dx,
                                     double inv_dy, double g, double dry_depth) {
  double rate = 0.0;
#pragma omp simd reduction(max : rate)
  for (std::ptrdiff_t i = 0; i < nx; ++i) {
    const double neighbour =
        std::min(std::min(h[i - 1], h[i + 1]), std::min(h[i - stride], h[i + stride]));
    const double c = (neighbour < dry_depth ? 2.0 : 1.0) * std::sqrt(g * h[i]);
    rate = std::max(rate, (std::abs(u[i]) + c) * inv_dx + (std::abs(v[i]) + c) * inv_dy);
  }
  return rate;
}

void validate(const Grid2d& grid, const Physics& physics, const Scheme& scheme,
              const Boundaries2d& boundaries) {
  const char* axis[2] = {"x", "y"};
  for (int d = 0; d < 2; ++d) {
    require(grid.spacing[d] > 0.0 && std::isfinite(grid.spacing[d]),
            std::string("grid spacing in ") + axis[d] + " must be positive, got " +
                number(grid.spacing[d]));
    require(grid.cells[d] > 0, std::string("cell count in ") + axis[d] + " must be positive, got " +
                                   std::to_string(grid.cells[d]));
    require(std::isfinite(grid.origin[d]),
            std::string("grid origin in ") + axis[d] + " must be finite");
  }
  require(physics.gravity > 0.0, "gravity must be positive, got " + number(physics.gravity));
  require(physics.manning >= 0.0, "manning must be non-negative, got " + number(physics.manning));
  require(physics.dry_depth >= 0.0,
          "dry_depth must be non-negative, got " + number(physics.dry_depth));
  require(scheme.courant > 0.0 && scheme.courant <= 1.0,
          "courant must lie in (0, 1], got " + number(scheme.courant));
  const std::pair<const char*, const Boundary*> sides[4] = {{"x_min", &boundaries.x_min},
                                                            {"x_max", &boundaries.x_max},
                                                            {"y_min", &boundaries.y_min},
                                                            {"y_max", &boundaries.y_max}};
  for (const auto& [name, b] : sides) {
    require(std::isfinite(b->value), std::string("boundary ") + name + " value must be finite");
    require(b->kind != BoundaryKind::fixed_depth || b->value >= 0.0,
            std::string("boundary ") + name + " fixed_depth must be non-negative, got " +
                number(b->value));
  }
}

}  // namespace

struct Solver2d::Impl {
  Grid2d grid;
  Physics physics;
  Scheme scheme;
  Boundaries2d boundaries;
  std::shared_ptr<SubdomainLink> link;
  std::array<bool, 4> linked{false, false, false, false};
  PaddedLayout layout;
  std::vector<double> bed;  // padded
  PaddedFields state;       // U^n, ghosts and primitives always current
  PaddedFields stage;       // U^(1) of SSP-RK2
  std::vector<solver_2d::StageWorkspace> workspaces;
  std::vector<double> bed_cells;  // unpadded, for bed()
  // Unpadded copies of the state for depth() and the discharges, refreshed on demand.
  mutable std::vector<double> h_cells, hu_cells, hv_cells;
  mutable bool cells_current = false;
  // save_state(): the state with its primitives and ghosts, and the bed (the
  // stage and the workspaces are rewritten by every step before they are read).
  PaddedFields saved_state;
  std::vector<double> saved_bed, saved_bed_cells;
  bool has_saved_state = false;

  // The arrays save_state() copies, by name (a checkpoint's state file).
  template <class Self>
  static auto state_arrays(Self& m) {
    return std::array{std::pair{"h", &m.state.h},   std::pair{"hu", &m.state.hu},
                      std::pair{"hv", &m.state.hv}, std::pair{"eta", &m.state.eta},
                      std::pair{"u", &m.state.u},   std::pair{"v", &m.state.v},
                      std::pair{"bed", &m.bed},     std::pair{"bed_cells", &m.bed_cells}};
  }

  Impl(Grid2d g, Physics p, Scheme s, Boundaries2d b, std::shared_ptr<SubdomainLink> l)
      : grid(g),
        physics(p),
        scheme(s),
        boundaries(b),
        link(std::move(l)),
        linked(link ? link->linked_sides() : std::array<bool, 4>{false, false, false, false}),
        layout{g.cells[0], g.cells[1]},
        bed(layout.size()),
        state(layout.size()),
        stage(layout.size()),
        bed_cells(static_cast<std::size_t>(layout.nx * layout.ny)) {
    fill_ghosts(state);
  }

  std::size_t cell_count() const { return static_cast<std::size_t>(layout.nx * layout.ny); }
  bool parallel() const { return layout.nx * layout.ny > solver_2d::parallel_cell_count; }

  void fill_ghosts(PaddedFields& f) {
    solver_2d::fill_ghost_cells(layout, boundaries, linked, physics, f, bed);
    if (!link) return;
    const std::span<double> conserved[3] = {f.h, f.hu, f.hv};
    link->fill_ghosts(conserved);
    solver_2d::update_linked_ghost_primitives(layout, linked, physics, f, bed);
  }

  // Interior primitives of the state (after set_state / set_bed) and its
  // ghosts (the bed's across linked sides first).
  void refresh_state() {
    if (link) {
      const std::span<double> bed_array[1] = {bed};
      link->fill_ghosts(bed_array);
    }
    const std::ptrdiff_t nx = layout.nx, ny = layout.ny;
    for (std::ptrdiff_t j = 0; j < ny; ++j)
      for (std::ptrdiff_t i = 0; i < nx; ++i)
        solver_2d::update_primitives(state, bed.data(), layout.index(i, j), physics.dry_depth);
    fill_ghosts(state);
    cells_current = false;
  }

  void copy_cells() const {
    if (cells_current) return;
    const std::size_t n = cell_count();
    h_cells.resize(n);
    hu_cells.resize(n);
    hv_cells.resize(n);
    const std::ptrdiff_t nx = layout.nx, ny = layout.ny;
#pragma omp parallel for schedule(static) if (n > solver_2d::parallel_cell_count)
    for (std::ptrdiff_t j = 0; j < ny; ++j) {
      const std::ptrdiff_t from = layout.index(0, j);
      std::copy_n(state.h.begin() + from, nx, h_cells.begin() + j * nx);
      std::copy_n(state.hu.begin() + from, nx, hu_cells.begin() + j * nx);
      std::copy_n(state.hv.begin() + from, nx, hv_cells.begin() + j * nx);
    }
    cells_current = true;
  }

  solver_2d::StageArguments stage_arguments(double dt, double base_weight,
                                            bool with_friction) const {
    return {layout,
            &physics,
            &scheme,
            bed.data(),
            dt,
            1.0 / grid.spacing[0],
            1.0 / grid.spacing[1],
            base_weight,
            with_friction};
  }
};

Solver2d::Solver2d(Grid2d grid, Physics physics, Scheme scheme, Boundaries2d boundaries,
                   std::shared_ptr<SubdomainLink> link) {
  validate(grid, physics, scheme, boundaries);
  const std::array<bool, 4> linked =
      link ? link->linked_sides() : std::array<bool, 4>{false, false, false, false};
  for (int d = 0; d < 2; ++d)
    if (linked[2 * d] || linked[2 * d + 1])
      require(grid.cells[d] >= PaddedLayout::ghosts,
              std::string("a block of a decomposed grid needs at least 2 cells in ") +
                  (d == 0 ? "x" : "y") + ", got " + std::to_string(grid.cells[d]));
  impl_ = std::make_unique<Impl>(grid, physics, scheme, boundaries, std::move(link));
}

Solver2d::~Solver2d() = default;

std::size_t Solver2d::cell_count() const {
  return impl_->cell_count();
}

Grid2d sub_grid(const Grid2d& grid, std::array<int, 2> begin, std::array<int, 2> cells) {
  Grid2d part = grid;
  for (std::size_t d = 0; d < 2; ++d) {
    part.cells[d] = cells[d];
    part.origin[d] = grid.origin[d] + begin[d] * grid.spacing[d];
  }
  return part;
}

cosim::MeshGeometry cell_mesh(const Grid2d& g) {
  cosim::UniformGrid mesh;
  mesh.dim = 2;
  mesh.origin = {g.origin[0], g.origin[1], 0.0};
  mesh.spacing = {g.spacing[0], g.spacing[1], 1.0};
  mesh.cells = {g.cells[0], g.cells[1], 1};
  mesh.location = cosim::GridLocation::cell;
  return mesh;
}

std::size_t cell_at(const Grid2d& g, double x, double y) {
  const auto count = static_cast<std::size_t>(g.cells[0]) * static_cast<std::size_t>(g.cells[1]);
  const double position[2] = {x, y};
  std::size_t index[2];
  for (int d = 0; d < 2; ++d) {
    const double s = (position[d] - g.origin[d]) / g.spacing[d];
    // The upper edge of the domain belongs to the last cell.
    if (!(s >= 0.0 && s <= g.cells[d])) return count;
    index[d] = std::min(static_cast<std::size_t>(s), static_cast<std::size_t>(g.cells[d] - 1));
  }
  return index[0] + static_cast<std::size_t>(g.cells[0]) * index[1];
}

cosim::MeshGeometry Solver2d::cells() const {
  return cell_mesh(impl_->grid);
}

double Solver2d::cell_size(std::size_t) const {
  return impl_->grid.spacing[0] * impl_->grid.spacing[1];
}

std::size_t Solver2d::cell_at(double x, double y) const {
  return swe::cell_at(impl_->grid, x, y);
}

void Solver2d::set_state(std::span<const double> h, std::span<const double> hu,
                         std::span<const double> hv) {
  Impl& m = *impl_;
  const std::size_t n = m.cell_count();
  auto check_size = [n](std::span<const double> values, const char* name, bool may_be_empty) {
    require(values.size() == n || (may_be_empty && values.empty()),
            std::string(name) + " has " + std::to_string(values.size()) + " values for " +
                std::to_string(n) + " cells");
  };
  check_size(h, "depth", false);
  check_size(hu, "discharge_x", true);
  check_size(hv, "discharge_y", true);
  // The messages are built only for a cell that fails: this runs every step
  // of the two-phase mode.
  for (std::size_t c = 0; c < n; ++c) {
    if (!(h[c] >= 0.0 && std::isfinite(h[c])))
      require(false, "depth of cell " + std::to_string(c) +
                         " must be finite and non-negative, got " + number(h[c]));
    if (!((hu.empty() || std::isfinite(hu[c])) && (hv.empty() || std::isfinite(hv[c]))))
      require(false, "discharge of cell " + std::to_string(c) + " must be finite");
  }
  const std::ptrdiff_t nx = m.layout.nx;
  for (std::size_t c = 0; c < n; ++c) {
    const std::ptrdiff_t k =
        m.layout.index(static_cast<std::ptrdiff_t>(c) % nx, static_cast<std::ptrdiff_t>(c) / nx);
    const bool wet = h[c] >= m.physics.dry_depth;  // dry cells carry no momentum
    m.state.h[k] = h[c];
    m.state.hu[k] = wet && !hu.empty() ? hu[c] : 0.0;
    m.state.hv[k] = wet && !hv.empty() ? hv[c] : 0.0;
  }
  m.refresh_state();
}

void Solver2d::set_bed(std::span<const double> bed) {
  Impl& m = *impl_;
  const std::size_t n = m.cell_count();
  require(bed.size() == n,
          "bed has " + std::to_string(bed.size()) + " values for " + std::to_string(n) + " cells");
  for (std::size_t c = 0; c < n; ++c)
    if (!std::isfinite(bed[c]))
      require(false, "bed of cell " + std::to_string(c) + " must be finite");
  const std::ptrdiff_t nx = m.layout.nx;
  for (std::size_t c = 0; c < n; ++c)
    m.bed[m.layout.index(static_cast<std::ptrdiff_t>(c) % nx,
                         static_cast<std::ptrdiff_t>(c) / nx)] = bed[c];
  m.bed_cells.assign(bed.begin(), bed.end());
  m.refresh_state();
}

double Solver2d::stable_time_step() const {
  const Impl& m = *impl_;
  const PaddedLayout& layout = m.layout;
  const std::ptrdiff_t nx = layout.nx, ny = layout.ny, sx = layout.stride();
  const double inv_dx = 1.0 / m.grid.spacing[0], inv_dy = 1.0 / m.grid.spacing[1];
  const double g = m.physics.gravity, dry_depth = m.physics.dry_depth;
  const double* h = m.state.h.data();
  const double* u = m.state.u.data();
  const double* v = m.state.v.data();
  double rate = 0.0;
#pragma omp parallel for schedule(static) reduction(max : rate) if (m.parallel())
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    const std::ptrdiff_t row = layout.index(0, j);
    rate = std::max(rate,
                    max_wave_rate(h + row, u + row, v + row, nx, sx, inv_dx, inv_dy, g, dry_depth));
  }
  if (m.link) rate = m.link->max(rate);
  return rate > 0.0 ? m.scheme.courant / rate : std::numeric_limits<double>::infinity();
}

void Solver2d::step(double dt) {
  Impl& m = *impl_;
  require(dt >= 0.0 && std::isfinite(dt),
          "time step must be finite and non-negative, got " + number(dt));
  // SSP-RK2 (Gottlieb & Shu, Math. Comp. 67, 1998). Stage 1: U1 = U^n - dt R(U^n).
  solver_2d::runge_kutta_stage(m.stage_arguments(dt, 0.0, false), m.state, m.state, m.stage,
                               m.workspaces);
  m.fill_ghosts(m.stage);
  // Stage 2: U^(n+1) = (U^n + U1 - dt R(U1)) / 2, then Manning friction.
  solver_2d::runge_kutta_stage(m.stage_arguments(dt, 0.5, true), m.stage, m.state, m.state,
                               m.workspaces);
  m.fill_ghosts(m.state);
  m.cells_current = false;
}

void Solver2d::save_state() {
  Impl& m = *impl_;
  m.saved_state = m.state;
  m.saved_bed = m.bed;
  m.saved_bed_cells = m.bed_cells;
  m.has_saved_state = true;
}

void Solver2d::restore_state() {
  Impl& m = *impl_;
  if (!m.has_saved_state)
    throw cosim::Error(cosim::ExitCode::internal_error, "swe 2D solver: no saved state to restore");
  m.state = m.saved_state;
  m.bed = m.saved_bed;
  m.bed_cells = m.saved_bed_cells;
  m.cells_current = false;
}

void Solver2d::write_state(cosim::StateFileWriter& out) const {
  for (const auto& [name, values] : Impl::state_arrays(*impl_)) out.numbers(name, *values);
}

void Solver2d::read_state(const cosim::StateFileReader& in) {
  for (const auto& [name, values] : Impl::state_arrays(*impl_))
    in.numbers(name, values->size(), *values);
  impl_->cells_current = false;
}

void Solver2d::read_state(std::span<const cosim::StateFileReader* const> parts,
                          std::span<const std::array<cosim::decomposition::Range, 3>> written,
                          const std::array<std::int64_t, 3>& grid_cells,
                          const std::array<cosim::decomposition::Range, 3>& mine) {
  using cosim::decomposition::StoredBlock;
  for (const auto& [name, values] : Impl::state_arrays(*impl_)) {
    // The padded arrays hold the ghost layers; bed_cells the cells alone.
    const int g =
        std::string_view(name) == "bed_cells" ? 0 : static_cast<int>(PaddedLayout::ghosts);
    std::vector<StoredBlock> from;
    std::vector<std::vector<double>> arrays(parts.size());
    std::vector<std::span<const double>> spans;
    for (std::size_t p = 0; p < parts.size(); ++p) {
      from.push_back(StoredBlock::padded(written[p], {g, g, 0}));
      parts[p]->numbers(name, from.back().size(), arrays[p]);
      spans.emplace_back(arrays[p]);
    }
    const StoredBlock to = StoredBlock::padded(mine, {g, g, 0});
    if (cosim::decomposition::join_blocks(from, spans, grid_cells, to, *values) > 0)
      throw cosim::InputError(
          fmt::format("{} and the other parts of its checkpoint do not cover "
                      "this block's '{}'",
                      parts[0]->file().string(), name));
  }
  impl_->cells_current = false;
}

std::span<const double> Solver2d::depth() const {
  impl_->copy_cells();
  return impl_->h_cells;
}

std::span<const double> Solver2d::discharge_x() const {
  impl_->copy_cells();
  return impl_->hu_cells;
}

std::span<const double> Solver2d::discharge_y() const {
  impl_->copy_cells();
  return impl_->hv_cells;
}

std::span<const double> Solver2d::bed() const {
  return impl_->bed_cells;
}

Totals Solver2d::totals() const {
  const Impl& m = *impl_;
  const std::ptrdiff_t nx = m.layout.nx, ny = m.layout.ny;
  // Row sums, then the rows in order: the same totals on any thread count.
  std::vector<Totals> rows(static_cast<std::size_t>(ny));
#pragma omp parallel for schedule(static) if (m.parallel())
  for (std::ptrdiff_t j = 0; j < ny; ++j) {
    Totals& r = rows[j];
    for (std::ptrdiff_t i = 0; i < nx; ++i) {
      const std::ptrdiff_t c = m.layout.index(i, j);
      r.volume += m.state.h[c];
      r.momentum_x += m.state.hu[c];
      r.momentum_y += m.state.hv[c];
    }
  }
  Totals t;
  for (const Totals& r : rows) {
    t.volume += r.volume;
    t.momentum_x += r.momentum_x;
    t.momentum_y += r.momentum_y;
  }
  if (m.link) {
    std::array<double, 3> sums{t.volume, t.momentum_x, t.momentum_y};
    m.link->sum(sums);
    t = {sums[0], sums[1], sums[2]};
  }
  const double area = m.grid.spacing[0] * m.grid.spacing[1];
  t.volume *= area;
  t.momentum_x *= area;
  t.momentum_y *= area;
  return t;
}

const Physics& Solver2d::physics() const {
  return impl_->physics;
}
const Scheme& Solver2d::scheme() const {
  return impl_->scheme;
}
const Grid2d& Solver2d::grid() const {
  return impl_->grid;
}
SubdomainLink* Solver2d::link() const {
  return impl_->link.get();
}

}  // namespace swe

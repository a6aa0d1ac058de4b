#include "mpm/coupling/bed_elevation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace mpm::coupling {

namespace {

struct Plateau {
  double from, to, height;
};

// The plateaus that can reach the upper envelope over [x0, x1): a plateau is
// dropped when every bin it touches is fully covered by a strictly higher
// one. Bins are half the narrowest plateau wide, so each plateau fully
// covers at least one; the test is exact, and leaves about the top layer of
// points, which keeps the sweep below cheap (a soil body's interior never
// reaches it).
std::vector<Plateau> visible_plateaus(const std::vector<Plateau>& plateaus, double x0, double x1) {
  double narrowest = x1 - x0;
  for (const Plateau& p : plateaus) narrowest = std::min(narrowest, p.to - p.from);
  const double width = 0.5 * narrowest;
  const double bins_wanted = (x1 - x0) / width;
  if (!(width > 0.0) || bins_wanted > 4.0 * static_cast<double>(plateaus.size()) + 1024.0)
    return plateaus;
  const int bins = static_cast<int>(std::ceil(bins_wanted));
  auto bin_of = [&](double x) {
    return std::clamp(static_cast<int>(std::floor((x - x0) / width)), 0, bins - 1);
  };
  std::vector<double> covered_to(static_cast<std::size_t>(bins),
                                 -std::numeric_limits<double>::infinity());
  for (const Plateau& p : plateaus) {
    const int first = static_cast<int>(std::ceil((p.from - x0) / width));  // bins inside [from, to]
    const int last = static_cast<int>(std::floor((p.to - x0) / width)) - 1;
    for (int b = std::max(first, 0); b <= std::min(last, bins - 1); ++b)
      covered_to[static_cast<std::size_t>(b)] =
          std::max(covered_to[static_cast<std::size_t>(b)], p.height);
  }
  std::vector<Plateau> visible;
  for (const Plateau& p : plateaus) {
    if (!(std::min(p.to, x1) > std::max(p.from, x0))) continue;
    bool hidden = true;
    for (int b = bin_of(p.from); hidden && b <= bin_of(p.to); ++b)
      hidden = covered_to[static_cast<std::size_t>(b)] > p.height;
    if (!hidden) visible.push_back(p);
  }
  return visible;
}

// Adds weight x (cell average of the upper envelope of `plateaus`, the
// bottom where none is) to out[0..n) for the n cells of width dx from x0.
void add_envelope_averages(const std::vector<Plateau>& plateaus, double x0, double dx, int n,
                           double bottom, double weight, double* out) {
  const double x1 = x0 + n * dx;
  struct Event {
    double x;
    bool start;
    double height;
  };
  std::vector<Event> events;
  const std::vector<Plateau> visible = visible_plateaus(plateaus, x0, x1);
  events.reserve(2 * visible.size() + 2);
  for (const Plateau& p : visible) {
    const double a = std::max(p.from, x0), b = std::min(p.to, x1);
    if (!(b > a)) continue;
    events.push_back({a, true, p.height});
    events.push_back({b, false, p.height});
  }
  std::sort(events.begin(), events.end(), [](const Event& l, const Event& r) { return l.x < r.x; });
  std::multiset<double> active;
  auto add_segment = [&](double a, double b, double value) {
    if (!(b > a)) return;
    int i = std::clamp(static_cast<int>(std::floor((a - x0) / dx)), 0, n - 1);
    for (; i < n; ++i) {
      const double lo = x0 + i * dx, hi = lo + dx;
      if (lo >= b) break;
      const double overlap = std::min(b, hi) - std::max(a, lo);
      if (overlap > 0.0) out[i] += weight * value * overlap / dx;
    }
  };
  double x = x0;
  for (const Event& e : events) {
    const double top = active.empty() ? bottom : std::max(bottom, *active.rbegin());
    add_segment(x, e.x, top);
    x = e.x;
    if (e.start)
      active.insert(e.height);
    else
      active.erase(active.find(e.height));
  }
  add_segment(x, x1, bottom);
}

// On ranks: every rank's plateaus on each line, those a higher one of the
// same rank hides left out (they are hidden among all ranks' too).
void join_ranks_plateaus(std::vector<std::vector<Plateau>>& on_line, double x0, double x1,
                         const GatherOverRanks& gather) {
  std::vector<double> mine;
  for (std::size_t k = 0; k < on_line.size(); ++k)
    for (const Plateau& p : visible_plateaus(on_line[k], x0, x1))
      mine.insert(mine.end(), {static_cast<double>(k), p.from, p.to, p.height});
  const std::vector<double> all = gather(mine);
  for (auto& line : on_line) line.clear();
  for (std::size_t i = 0; i + 3 < all.size(); i += 4)
    on_line[static_cast<std::size_t>(all[i])].push_back({all[i + 1], all[i + 2], all[i + 3]});
}

}  // namespace

template <int Dim>
std::vector<double> bed_elevation(const SurfaceGrid<Dim>& surface, const Particles<Dim>& particles,
                                  const std::vector<BodyRole>& roles, int strips,
                                  const GatherOverRanks& gather_over_ranks) {
  constexpr int up = Dim - 1;
  std::vector<double> bed(surface.size(), 0.0);
  auto plateau_of = [&](std::size_t p) {
    const Vec<Dim>& x = particles.position[p];
    const Vec<Dim>& l = particles.half_length[p];
    return Plateau{x[0] - l[0], x[0] + l[0], x[up] + l[up]};
  };
  const double x0 = surface.origin[0];
  const double x1 = x0 + surface.cells[0] * surface.spacing[0];
  if constexpr (Dim == 2) {
    std::vector<std::vector<Plateau>> plateaus(1);
    for (std::size_t p = 0; p < particles.size(); ++p)
      if (roles[particles.body[p]].bed) plateaus[0].push_back(plateau_of(p));
    if (gather_over_ranks) join_ranks_plateaus(plateaus, x0, x1, gather_over_ranks);
    add_envelope_averages(plateaus[0], x0, surface.spacing[0], surface.cells[0], surface.bottom,
                          1.0, bed.data());
  } else {
    // Lines across y at the centres of `strips` equal strips of every row of cells.
    const int rows = surface.cells[1];
    const int lines = rows * strips;
    const double dy = surface.spacing[1] / strips;
    std::vector<std::vector<Plateau>> on_line(static_cast<std::size_t>(lines));
    for (std::size_t p = 0; p < particles.size(); ++p) {
      if (!roles[particles.body[p]].bed) continue;
      const double y = particles.position[p][1], ly = particles.half_length[p][1];
      // Lines k with y_k = y0 + (k + 1/2) dy inside [y - ly, y + ly].
      const double s0 = (y - ly - surface.origin[1]) / dy - 0.5;
      const double s1 = (y + ly - surface.origin[1]) / dy - 0.5;
      const int first = std::max(0, static_cast<int>(std::ceil(s0)));
      const int last = std::min(lines - 1, static_cast<int>(std::floor(s1)));
      for (int k = first; k <= last; ++k)
        on_line[static_cast<std::size_t>(k)].push_back(plateau_of(p));
    }
    if (gather_over_ranks) join_ranks_plateaus(on_line, x0, x1, gather_over_ranks);
    const auto nx = static_cast<std::size_t>(surface.cells[0]);
    for (int k = 0; k < lines; ++k)
      add_envelope_averages(on_line[static_cast<std::size_t>(k)], x0, surface.spacing[0],
                            surface.cells[0], surface.bottom, 1.0 / strips,
                            bed.data() + static_cast<std::size_t>(k / strips) * nx);
  }
  return bed;
}

template std::vector<double> bed_elevation<2>(const SurfaceGrid<2>&, const Particles<2>&,
                                              const std::vector<BodyRole>&, int,
                                              const GatherOverRanks&);
template std::vector<double> bed_elevation<3>(const SurfaceGrid<3>&, const Particles<3>&,
                                              const std::vector<BodyRole>&, int,
                                              const GatherOverRanks&);

}  // namespace mpm::coupling

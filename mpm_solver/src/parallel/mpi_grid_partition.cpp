#include "mpm/parallel/mpi_grid_partition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "../solver/particle_bins.hpp"
#include "cosim/decomposition/balanced_cuts.hpp"
#include "cosim/error.hpp"

namespace mpm::parallel {

namespace {

using detail::ParticleBins;

// Adds the wall time of its scope to `seconds`.
class Stopwatch {
 public:
  explicit Stopwatch(double& seconds) : seconds_(seconds), start_(MPI_Wtime()) {}
  ~Stopwatch() { seconds_ += MPI_Wtime() - start_; }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& seconds_;
  double start_;
};

int row_count(const CaseDescription& d) {
  return d.grid.cells[static_cast<std::size_t>(d.dimension - 1)];
}

// The points seeded in each slab of the scatter.
std::vector<double> points_per_slab(const CaseDescription& d) {
  const int rows = row_count(d);
  const auto last = static_cast<Eigen::Index>(d.dimension - 1);
  std::vector<double> weights(static_cast<std::size_t>(ParticleBins::slab_of_row(rows - 1) + 1),
                              0.0);
  for (const BodySpec& body : d.bodies)
    for (const Vec3d& x : body.positions) {
      const double row = std::floor((x[last] - d.grid.origin[last]) / d.grid.spacing[last]);
      const int r = static_cast<int>(std::clamp(row, 0.0, static_cast<double>(rows - 1)));
      weights[static_cast<std::size_t>(ParticleBins::slab_of_row(r))] += 1.0;
    }
  return weights;
}

int intersection_size(std::array<int, 2> r) {
  return std::max(0, r[1] - r[0]);
}

}  // namespace

std::vector<int> balanced_row_cuts(const CaseDescription& description, int ranks) {
  const int rows = row_count(description);
  const std::vector<double> weights = points_per_slab(description);
  if (static_cast<int>(weights.size()) < ranks)
    throw cosim::InputError(
        fmt::format("{} cell rows along the last direction make {} slabs of {} rows, fewer "
                    "than the {} ranks (each rank needs at least one slab)",
                    rows, weights.size(), ParticleBins::slab_rows, ranks));
  const auto slab_cuts = cosim::decomposition::balanced_cuts(weights, ranks, 1);
  std::vector<int> cuts;
  for (const auto slab : slab_cuts)
    cuts.push_back(std::min(rows, static_cast<int>(slab) * ParticleBins::slab_rows));
  return cuts;
}

double row_imbalance(const CaseDescription& description, const std::vector<int>& cuts) {
  const std::vector<double> weights = points_per_slab(description);
  std::vector<std::int64_t> slab_cuts;
  for (const int row : cuts)
    slab_cuts.push_back((row + ParticleBins::slab_rows - 1) / ParticleBins::slab_rows);
  return cosim::decomposition::imbalance(weights, slab_cuts);
}

template <int Dim>
MpiGridPartition<Dim>::MpiGridPartition(MPI_Comm comm, std::vector<int> cuts, double origin,
                                        double spacing)
    : origin_(origin), spacing_(spacing) {
  MPI_Comm_dup(comm, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  recut(std::move(cuts));
  migration_ = std::make_unique<ParticleMigration<Dim>>(
      comm_, [this](const Vec<Dim>& x) { return owner(x); });
  std::vector<int> neighbours;
  for (const int q : {rank_ - 1, rank_ + 1})
    if (q >= 0 && q < ranks_) neighbours.push_back(q);
  migration_->set_neighbours(std::move(neighbours));
}

template <int Dim>
MpiGridPartition<Dim>::~MpiGridPartition() {
  migration_.reset();
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

template <int Dim>
void MpiGridPartition<Dim>::recut(std::vector<int> cuts) {
  const bool whole_slabs = std::all_of(cuts.begin(), cuts.end() - 1,
                                       [](int row) { return row % ParticleBins::slab_rows == 0; });
  if (static_cast<int>(cuts.size()) != ranks_ + 1 || cuts.front() != 0 || !whole_slabs ||
      std::adjacent_find(cuts.begin(), cuts.end(), std::greater_equal<>()) != cuts.end() ||
      (!cuts_.empty() && cuts.back() != cuts_.back()))
    throw cosim::Error(cosim::ExitCode::internal_error,
                       "MPM grid partition: cuts that do not match the ranks and slabs");
  cuts_ = std::move(cuts);
}

// This rank's points per slab, summed over the ranks.
template <int Dim>
std::vector<double> MpiGridPartition<Dim>::points_per_slab(const Particles<Dim>& particles) const {
  std::vector<double> weights(
      static_cast<std::size_t>(ParticleBins::slab_of_row(cuts_.back() - 1) + 1), 0.0);
  for (const Vec<Dim>& x : particles.position)
    weights[static_cast<std::size_t>(ParticleBins::slab_of_row(row_of(x)))] += 1.0;
  MPI_Allreduce(MPI_IN_PLACE, weights.data(), static_cast<int>(weights.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  return weights;
}

template <int Dim>
double MpiGridPartition<Dim>::imbalance(const Particles<Dim>& particles) const {
  double counts[2] = {static_cast<double>(particles.size()), static_cast<double>(particles.size())};
  MPI_Allreduce(MPI_IN_PLACE, &counts[0], 1, MPI_DOUBLE, MPI_MAX, comm_);
  MPI_Allreduce(MPI_IN_PLACE, &counts[1], 1, MPI_DOUBLE, MPI_SUM, comm_);
  return counts[1] > 0.0 ? counts[0] / (counts[1] / ranks_) : 0.0;
}

template <int Dim>
bool MpiGridPartition<Dim>::rebalance(const Particles<Dim>& particles, double threshold) {
  const Stopwatch watch(communication_seconds_);
  const std::vector<double> weights = points_per_slab(particles);
  const auto slab_cuts_of = [](const std::vector<int>& rows) {
    std::vector<std::int64_t> slabs;
    for (const int row : rows)
      slabs.push_back((row + ParticleBins::slab_rows - 1) / ParticleBins::slab_rows);
    return slabs;
  };
  const double now = cosim::decomposition::imbalance(weights, slab_cuts_of(cuts_));
  if (!(now > threshold)) return false;
  const auto balanced = cosim::decomposition::balanced_cuts(weights, ranks_, 1);
  std::vector<int> rows;
  for (const auto slab : balanced)
    rows.push_back(std::min(cuts_.back(), static_cast<int>(slab) * ParticleBins::slab_rows));
  if (rows == cuts_ || !(cosim::decomposition::imbalance(weights, balanced) < now)) return false;
  recut(std::move(rows));
  return true;
}

template <int Dim>
std::array<int, 2> MpiGridPartition<Dim>::owned_rows() const {
  return {cuts_[static_cast<std::size_t>(rank_)], cuts_[static_cast<std::size_t>(rank_) + 1]};
}

template <int Dim>
int MpiGridPartition<Dim>::row_of(const Vec<Dim>& x) const {
  const double row = std::floor((x[Dim - 1] - origin_) / spacing_);
  const double last = static_cast<double>(cuts_.back() - 1);
  return static_cast<int>(std::clamp(std::isfinite(row) ? row : 0.0, 0.0, last));
}

template <int Dim>
int MpiGridPartition<Dim>::owner(const Vec<Dim>& x) const {
  const auto above = std::upper_bound(cuts_.begin(), cuts_.end(), row_of(x));
  return static_cast<int>(above - cuts_.begin()) - 1;
}

template <int Dim>
void MpiGridPartition<Dim>::set_planes(const PlaneRanges& planes, std::size_t plane_size,
                                       int fields) {
  plane_size_ = plane_size;
  fields_ = fields;
  const int mine[4] = {planes.stored_first, planes.stored_end, planes.owned_first,
                       planes.owned_end};
  std::vector<int> all(4 * static_cast<std::size_t>(ranks_));
  MPI_Allgather(mine, 4, MPI_INT, all.data(), 4, MPI_INT, comm_);
  planes_.resize(static_cast<std::size_t>(ranks_));
  for (std::size_t r = 0; r < planes_.size(); ++r)
    planes_[r] = {all[4 * r], all[4 * r + 1], all[4 * r + 2], all[4 * r + 3]};
}

// Ghosts to owners: what I store and q owns. Owners to ghosts: what I own
// and q stores.
template <int Dim>
std::array<int, 2> MpiGridPartition<Dim>::sent_planes(int q, bool to_owners) const {
  const PlaneRanges& me = planes_[static_cast<std::size_t>(rank_)];
  const PlaneRanges& other = planes_[static_cast<std::size_t>(q)];
  return to_owners ? std::array{std::max(me.stored_first, other.owned_first),
                                std::min(me.stored_end, other.owned_end)}
                   : std::array{std::max(me.owned_first, other.stored_first),
                                std::min(me.owned_end, other.stored_end)};
}

template <int Dim>
std::array<int, 2> MpiGridPartition<Dim>::received_planes(int q, bool to_owners) const {
  const PlaneRanges& me = planes_[static_cast<std::size_t>(rank_)];
  const PlaneRanges& other = planes_[static_cast<std::size_t>(q)];
  return to_owners ? std::array{std::max(me.owned_first, other.stored_first),
                                std::min(me.owned_end, other.stored_end)}
                   : std::array{std::max(me.stored_first, other.owned_first),
                                std::min(me.stored_end, other.owned_end)};
}

template <int Dim>
void MpiGridPartition<Dim>::transfer(std::span<const GridArray> arrays, bool to_owners) {
  const Stopwatch watch(communication_seconds_);
  const PlaneRanges& me = planes_[static_cast<std::size_t>(rank_)];
  const auto stored_values =
      static_cast<std::size_t>(me.stored_end - me.stored_first) * plane_size_;
  // f(first number, count) over the numbers of planes [first, end) of every
  // array and field, in one order on both sides.
  const auto for_each_run = [&](std::array<int, 2> range, auto&& f) {
    const auto planes = static_cast<std::size_t>(intersection_size(range));
    if (planes == 0) return;
    for (const GridArray& a : arrays) {
      const auto c = static_cast<std::size_t>(a.components);
      const int blocks = a.fields > 0 ? a.fields : fields_;
      for (int field = 0; field < blocks; ++field) {
        const std::size_t value =
            static_cast<std::size_t>(field) * stored_values +
            static_cast<std::size_t>(range[0] - me.stored_first) * plane_size_;
        f(a.data + value * c, planes * plane_size_ * c);
      }
    }
  };
  std::vector<MPI_Request> requests;
  const int neighbours[2] = {rank_ - 1, rank_ + 1};
  for (int side = 0; side < 2; ++side) {
    const int q = neighbours[side];
    if (q < 0 || q >= ranks_) continue;
    auto& in = receive_[static_cast<std::size_t>(side)];
    in.clear();
    for_each_run(received_planes(q, to_owners),
                 [&](double*, std::size_t count) { in.resize(in.size() + count); });
    if (!in.empty()) {
      requests.emplace_back();
      MPI_Irecv(in.data(), static_cast<int>(in.size()), MPI_DOUBLE, q, 0, comm_, &requests.back());
    }
    auto& out = send_[static_cast<std::size_t>(side)];
    out.clear();
    for_each_run(sent_planes(q, to_owners), [&](double* data, std::size_t count) {
      out.insert(out.end(), data, data + count);
    });
    if (!out.empty()) {
      requests.emplace_back();
      MPI_Isend(out.data(), static_cast<int>(out.size()), MPI_DOUBLE, q, 0, comm_,
                &requests.back());
      values_sent_ += out.size();
    }
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (int side = 0; side < 2; ++side) {
    const int q = neighbours[side];
    if (q < 0 || q >= ranks_) continue;
    const double* at = receive_[static_cast<std::size_t>(side)].data();
    for_each_run(received_planes(q, to_owners), [&](double* data, std::size_t count) {
      if (to_owners) {
        for (std::size_t k = 0; k < count; ++k) data[k] += at[k];
      } else {
        std::copy(at, at + count, data);
      }
      at += count;
    });
  }
}

template <int Dim>
void MpiGridPartition<Dim>::accumulate(std::span<const GridArray> arrays) {
  transfer(arrays, /*to_owners=*/true);
}

template <int Dim>
void MpiGridPartition<Dim>::exchange(std::span<const GridArray> arrays) {
  transfer(arrays, /*to_owners=*/false);
}

template <int Dim>
double MpiGridPartition<Dim>::max(double local) {
  const Stopwatch watch(communication_seconds_);
  double global = local;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return global;
}

template <int Dim>
void MpiGridPartition<Dim>::sum(std::span<double> values) {
  const Stopwatch watch(communication_seconds_);
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
}

template <int Dim>
void MpiGridPartition<Dim>::max(std::span<double> values) {
  const Stopwatch watch(communication_seconds_);
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX,
                comm_);
}

template <int Dim>
std::vector<double> MpiGridPartition<Dim>::gather(std::span<const double> values) {
  const Stopwatch watch(communication_seconds_);
  const int mine = static_cast<int>(values.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks_)), offsets(counts.size(), 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(static_cast<std::size_t>(offsets.back() + counts.back()));
  MPI_Allgatherv(values.data(), mine, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, comm_);
  return all;
}

// The points kept stay in id order and each sender's arrive in id order;
// one sort by id puts them together as one process holds them.
template <int Dim>
void MpiGridPartition<Dim>::migrate(Particles<Dim>& particles) {
  if (ranks_ == 1) return;
  const Stopwatch watch(communication_seconds_);
  const auto moved = migration_->migrate(particles);
  points_sent_ += moved.sent;
  if (moved.received > 0) particles.sort_by_id();
}

template class MpiGridPartition<2>;
template class MpiGridPartition<3>;

}  // namespace mpm::parallel

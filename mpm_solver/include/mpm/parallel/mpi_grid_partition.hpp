#pragma once

#include <mpi.h>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "mpm/case/case_description.hpp"
#include "mpm/parallel/particle_migration.hpp"
#include "mpm/solver/grid_partition.hpp"

namespace mpm::parallel {

// Where to cut the cell rows (along the grid's last direction) of a case
// over `ranks` ranks: at whole slabs of the particle-to-grid scatter, so
// that the weight of the points seeded in each part is as even as the slabs
// allow (cosim::decomposition::balanced_cuts). Returns ranks + 1 rows, 0
// first and the row count last; rank r owns [cuts[r], cuts[r + 1]).
// Throws cosim::InputError when the grid has fewer slabs than ranks.
std::vector<int> balanced_row_cuts(const CaseDescription& description, int ranks);

// The largest part's point count over the mean part's, for the cuts above.
double row_imbalance(const CaseDescription& description, const std::vector<int>& cuts);

// GridPartition over the ranks of an MPI communicator: ghost planes go to
// and come from the two neighbouring ranks in one message each way, the
// reductions are MPI_Allreduce, and points migrate with ParticleMigration.
template <int Dim>
class MpiGridPartition final : public GridPartition<Dim> {
 public:
  // `cuts` as balanced_row_cuts gives them, for comm's ranks; `origin` and
  // `spacing` of the grid's last direction place a point in its row.
  MpiGridPartition(MPI_Comm comm, std::vector<int> cuts, double origin, double spacing);
  ~MpiGridPartition() override;
  MpiGridPartition(const MpiGridPartition&) = delete;
  MpiGridPartition& operator=(const MpiGridPartition&) = delete;

  std::array<int, 2> owned_rows() const override;
  void set_planes(const PlaneRanges& planes, std::size_t plane_size, int fields) override;
  void accumulate(std::span<const GridArray> arrays) override;
  void exchange(std::span<const GridArray> arrays) override;
  double max(double local) override;
  void sum(std::span<double> values) override;
  void max(std::span<double> values) override;
  std::vector<double> gather(std::span<const double> values) override;
  void migrate(Particles<Dim>& particles) override;

  // The points of the fullest rank over the mean (1: balanced) (collective).
  double imbalance(const Particles<Dim>& particles) const;
  // Cuts balanced for the ranks' `particles` now (balanced_cuts of the points
  // per slab); when the current cuts' imbalance exceeds `threshold` and the
  // new ones do better, takes them and returns true: the solver must then
  // repartition() (collective).
  bool rebalance(const Particles<Dim>& particles, double threshold);
  // Takes `cuts` (ranks + 1 rows at whole slabs, as balanced_row_cuts gives)
  // as the rows of each rank; the solver must then repartition().
  void recut(std::vector<int> cuts);
  const std::vector<int>& cuts() const { return cuts_; }

  int rank() const { return rank_; }
  // The rank that owns the point at x.
  int owner(const Vec<Dim>& x) const;
  // Grid values this rank has sent in accumulate() and exchange(), and
  // points it has sent away in migrate(), since construction.
  std::size_t values_sent() const { return values_sent_; }
  std::size_t points_sent() const { return points_sent_; }
  // Wall time spent in the partition's communication since construction
  // (waiting for the other ranks included).
  double communication_seconds() const { return communication_seconds_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, ranks_ = 1;
  std::vector<int> cuts_;
  double origin_, spacing_;
  std::vector<PlaneRanges> planes_;  // of every rank
  std::size_t plane_size_ = 0;
  int fields_ = 1;
  std::unique_ptr<ParticleMigration<Dim>> migration_;
  std::array<std::vector<double>, 2> send_, receive_;  // per neighbour: below, above
  std::size_t values_sent_ = 0, points_sent_ = 0;
  double communication_seconds_ = 0.0;

  // The cell row of a point, clamped to the grid.
  int row_of(const Vec<Dim>& x) const;
  std::vector<double> points_per_slab(const Particles<Dim>& particles) const;
  // Planes [first, end) this rank sends to neighbour q and receives from
  // it: ghosts to owners (`to_owners`) or owners to ghosts.
  std::array<int, 2> sent_planes(int q, bool to_owners) const;
  std::array<int, 2> received_planes(int q, bool to_owners) const;
  // Sends and receives the planes; `add` adds what arrives, else replaces.
  void transfer(std::span<const GridArray> arrays, bool to_owners);
};

extern template class MpiGridPartition<2>;
extern template class MpiGridPartition<3>;

}  // namespace mpm::parallel

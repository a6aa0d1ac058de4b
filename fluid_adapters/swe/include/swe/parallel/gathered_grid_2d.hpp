#pragma once

#include <mpi.h>

#include <vector>

#include "cosim/decomposition/cartesian_decomposition.hpp"
#include "swe/solver_2d.hpp"

namespace swe::parallel {

// The whole grid of a decomposed run, gathered on rank 0 from every rank's
// block for the outputs (snapshots, gauges, water.csv), so that they are
// the files a run on one rank writes: the same cells, the same order, the
// same totals bit for bit (summed as Solver2d sums them). A read-only
// Solver: the mutators throw cosim::Error (internal_error). On the other
// ranks it holds nothing and serves only to send.
class GatheredGrid2d final : public Solver {
 public:
  // `block` is this rank's solver of `decomposition`'s block; `grid` the whole grid.
  GatheredGrid2d(MPI_Comm comm, const cosim::decomposition::CartesianDecomposition& decomposition,
                 const Grid2d& grid, const Solver2d& block);

  // Copies every rank's block into the whole grid on rank 0 (collective).
  void gather();
  bool is_root() const { return rank_ == 0; }

  int dimension() const override { return 2; }
  std::size_t cell_count() const override;
  cosim::MeshGeometry cells() const override;
  double cell_size(std::size_t cell) const override;
  std::size_t cell_at(double x, double y = 0.0) const override;
  void set_state(std::span<const double>, std::span<const double>,
                 std::span<const double>) override;
  void set_bed(std::span<const double>) override;
  double stable_time_step() const override;
  void step(double) override;
  void save_state() override;
  void restore_state() override;
  void write_state(cosim::StateFileWriter&) const override;
  void read_state(const cosim::StateFileReader&) override;
  std::span<const double> depth() const override { return h_; }
  std::span<const double> discharge_x() const override { return hu_; }
  std::span<const double> discharge_y() const override { return hv_; }
  std::span<const double> bed() const override { return bed_; }
  Totals totals() const override;
  const Physics& physics() const override { return block_.physics(); }
  const Scheme& scheme() const override { return block_.scheme(); }

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  const Solver2d& block_;
  Grid2d grid_;
  std::vector<cosim::decomposition::Block> blocks_;
  std::vector<int> counts_, displacements_;
  std::vector<double> received_, h_, hu_, hv_, bed_;
};

}  // namespace swe::parallel

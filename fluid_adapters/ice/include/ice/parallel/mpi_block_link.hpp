#pragma once

#include <mpi.h>

#include <cstddef>
#include <memory>

#include "cosim/decomposition/halo_exchange.hpp"
#include "ice/case/case_description.hpp"
#include "ice/parallel/petsc_pressure_solver.hpp"
#include "ice/solver/block_link.hpp"
#include "ice/solver/ice_solver.hpp"

// The ICE solver decomposed over MPI ranks (issue 27): each rank steps its
// block of the grid widened by ghost layers toward its neighbours, linked to
// the others by a halo exchange and reductions, its pressure solved with
// theirs by PETSc.
namespace ice::parallel {

// Ghost layers of a block: more than the cells a step's explicit stages
// carry the widened edge's wall inward (face velocities, divergence, face
// pressures, Lagrangian values, viscous and conductive fluxes, limited
// advection). Measured by ice_decomposed_test (tests/mpi): a viscous dam
// break agrees with the whole grid from 3 layers, with Smagorinsky's eddy
// viscosity and heat conduction from 4; one more for margin.
inline constexpr int ghost_layers = 5;

template <int Dim>
class MpiBlockLink final : public BlockLink<Dim> {
 public:
  // The rank's block of `decomposition` (over every rank of `comm`). Throws
  // cosim::InputError for a block narrower than the ghost layers along a
  // divided direction.
  MpiBlockLink(MPI_Comm comm, const cosim::decomposition::CartesianDecomposition& decomposition,
               int ghosts = ghost_layers);
  ~MpiBlockLink() override;
  MpiBlockLink(const MpiBlockLink&) = delete;
  MpiBlockLink& operator=(const MpiBlockLink&) = delete;

  std::array<typename BlockLink<Dim>::Range, static_cast<std::size_t>(Dim)> owned_cells()
      const override;
  void fill_ghosts(std::span<const std::span<double>> fields) override;
  double max(double local) override;
  void sum(std::span<double> values) override;

  const cosim::decomposition::HaloExchange& halo() const { return halo_; }
  MPI_Comm communicator() const { return comm_; }
  // The widened block: its grid within `whole`, and its first cell's indices there.
  CellGrid<Dim> block_grid(const CellGrid<Dim>& whole) const;
  std::array<int, static_cast<std::size_t>(Dim)> offset() const;
  // Seconds in fill_ghosts and the reductions, and the values sent, since construction.
  double communication_seconds() const { return seconds_; }
  std::size_t values_sent() const { return values_sent_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  cosim::decomposition::HaloExchange halo_;
  double seconds_ = 0.0;
  std::size_t values_sent_ = 0;
};

// One rank's part of a case decomposed over `comm`'s ranks.
template <int Dim>
struct BlockSolver {
  std::unique_ptr<IceSolver<Dim>> solver;
  std::shared_ptr<MpiBlockLink<Dim>> link;
  cosim::decomposition::CartesianDecomposition decomposition;
};

// The case's grid split over `comm`'s ranks (cosim::decomposition::
// process_grid: the least halo) and this rank's block solver: the initial
// state of its widened block (the case's fill of the whole grid, so that a
// hydrostatic column is integrated whole), the case's sides on the grid's
// edges and walls toward the neighbours (their ghosts are refreshed), and
// the pressure solved by PETSc with `pressure`. PETSc must be initialised
// (PetscLibrary). Collective. Throws cosim::InputError when a block would be
// narrower than the ghost layers.
template <int Dim>
BlockSolver<Dim> make_block_solver(MPI_Comm comm, const CaseDescription& description,
                                   const PetscPressureOptions& pressure, int ghosts = ghost_layers);

extern template class MpiBlockLink<1>;
extern template class MpiBlockLink<2>;
extern template class MpiBlockLink<3>;

}  // namespace ice::parallel

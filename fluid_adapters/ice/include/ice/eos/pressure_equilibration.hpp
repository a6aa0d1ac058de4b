#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "ice/eos/equation_of_state.hpp"

namespace ice {

inline constexpr double one_atmosphere = 101325.0;  // [Pa]

struct EquilibrationOptions {
  double tolerance = 1e-12;  // converged when |sum_f phi_f - n| <= tolerance * n
  int max_iterations = 100;
};

// The common pressure of the fluid materials of one cell and what follows
// from it, per material in the order given.
struct CellEquilibrium {
  double pressure = 0.0;  // P [Pa]
  int iterations = 0;     // Newton (or bisection) updates of P until |residual| <= tolerance n
  double residual = 0.0;  // sum_f phi_f - n at P, after one more (uncounted) Newton correction
  std::vector<double> density;          // rho_f(P, T_f) [kg/m3]
  std::vector<double> volume_fraction;  // phi_f = rhobar_f / rho_f; they sum to n
  std::vector<double> compressibility;  // kappa_f = 1 / (rho_f (dP/drho)_T) [1/Pa]
};

// A cell whose pressure could not be equilibrated: bad input (iterations 0)
// or no convergence. It carries the iterations taken, the last pressure and
// residual, and, once the batched solve has added it, the cell index.
class PressureEquilibrationError : public cosim::NumericalError {
 public:
  PressureEquilibrationError(const std::string& what, int iterations, double pressure,
                             double residual, std::optional<std::size_t> cell = std::nullopt);

  int iterations() const { return iterations_; }
  double pressure() const { return pressure_; }
  double residual() const { return residual_; }
  std::optional<std::size_t> cell() const { return cell_; }

  // The same error with "cell <index>: " in front of its message.
  PressureEquilibrationError in_cell(std::size_t cell) const;

 private:
  std::string reason_;
  int iterations_;
  double pressure_;
  double residual_;
  std::optional<std::size_t> cell_;
};

// Tran et al., MPMICE, eqs. 42-43: the pressure P at which the fluid
// materials of a cell, each at its own temperature, fill its pores,
//
//   sum_f rhobar_f / rho_f(P, T_f) = n,   rhobar_f = M_f / V,  0 < n <= 1,
//
// by Newton's method on 1 / sum_f phi_f - 1 / n (exactly linear in P for a
// single ideal gas or linear water), kept inside the bracket (P_low, P_high):
// P_low starts at the largest minimum_pressure() of the materials (so every
// rho_f stays positive: an ideal gas keeps P > 0) and rises to each P where
// the materials still over-fill the pores; P_high is the lowest P where they
// under-fill them. A Newton step leaving the bracket is replaced by
// bisection. The iteration starts at
// `pressure_guess` (the cell's previous pressure), or P_min + 1 atm when the
// guess is not above P_min. A material with rhobar_f = 0 is absent
// (phi_f = 0) but still gets rho_f(P, T_f).
//
// Throws PressureEquilibrationError for non-positive or non-finite porosity
// above 1, negative or non-finite bulk densities or all zero, non-positive
// temperatures, a cell whose present materials cannot fill the pores above
// an absent material's minimum pressure, or no convergence within
// options.max_iterations; std::invalid_argument for mismatched sizes, a null
// model or nonsensical options.
CellEquilibrium equilibrate_pressure(std::span<const EquationOfState* const> materials,
                                     std::span<const double> bulk_density,
                                     std::span<const double> temperature, double porosity,
                                     double pressure_guess = one_atmosphere,
                                     const EquilibrationOptions& options = {});

// One fluid material over the cells of a grid.
struct MaterialCells {
  const EquationOfState* eos = nullptr;
  std::span<const double> bulk_density;  // rhobar_f per cell [kg/m3]
  std::span<const double> temperature;   // T_f per cell [K]
};

// The equilibrium of every cell: per cell, and per material then cell.
struct EquilibratedCells {
  std::vector<double> pressure;                      // [cell]
  std::vector<std::vector<double>> density;          // [material][cell]
  std::vector<std::vector<double>> volume_fraction;  // [material][cell]
  std::vector<std::vector<double>> compressibility;  // [material][cell]
  int most_iterations = 0;                           // over all cells

  // Work arrays of the batched solve, kept so that repeated calls into the
  // same result allocate nothing; not part of the result.
  struct Workspace {
    std::vector<double> low, high, pressure, residual, slope;
    std::vector<int> iterations;
    std::vector<std::size_t> active, one_by_one;
  } workspace;
};

// equilibrate_pressure() in every cell. `pressure_guess` has one entry per
// cell, or none (one atmosphere everywhere). The error of a failing cell is
// rethrown with its index. The second form reuses `result`'s storage.
EquilibratedCells equilibrate_pressure(std::span<const MaterialCells> materials,
                                       std::span<const double> porosity,
                                       std::span<const double> pressure_guess,
                                       const EquilibrationOptions& options = {});
void equilibrate_pressure(std::span<const MaterialCells> materials,
                          std::span<const double> porosity, std::span<const double> pressure_guess,
                          const EquilibrationOptions& options, EquilibratedCells& result);

// The mixture compressibility of MPMICE eq. 52,
// kappa = sum_f phi_f kappa_f / sum_f phi_f [1/Pa].
double mixture_compressibility(std::span<const double> volume_fraction,
                               std::span<const double> compressibility);

}  // namespace ice

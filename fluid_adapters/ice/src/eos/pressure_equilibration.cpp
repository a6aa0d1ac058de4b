#include "ice/eos/pressure_equilibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ice/eos/model_dispatch.hpp"

namespace ice {

PressureEquilibrationError::PressureEquilibrationError(const std::string& what, int iterations,
                                                       double pressure, double residual,
                                                       std::optional<std::size_t> cell)
    : cosim::NumericalError(cell ? fmt::format("cell {}: {}", *cell, what) : what),
      reason_(what),
      iterations_(iterations),
      pressure_(pressure),
      residual_(residual),
      cell_(cell) {}

PressureEquilibrationError PressureEquilibrationError::in_cell(std::size_t cell) const {
  return PressureEquilibrationError(reason_, iterations_, pressure_, residual_, cell);
}

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

// The fluid materials of one cell, checked.
class PoreFilling {
 public:
  // `kinds` holds model_kind() of each material.
  PoreFilling(std::span<const EquationOfState* const> materials, std::span<const ModelKind> kinds,
              std::span<const double> bulk_density, std::span<const double> temperature,
              double porosity)
      : materials_(materials),
        kinds_(kinds),
        bulk_density_(bulk_density),
        temperature_(temperature),
        porosity_(porosity) {
    if (materials.empty()) throw std::invalid_argument("pressure equilibration: no fluid material");
    if (bulk_density.size() != materials.size() || temperature.size() != materials.size()) {
      throw std::invalid_argument(fmt::format(
          "pressure equilibration: {} materials but {} bulk densities and {} temperatures",
          materials.size(), bulk_density.size(), temperature.size()));
    }
    if (!(porosity > 0.0 && porosity <= 1.0))
      fail(fmt::format("porosity n = {} is outside (0, 1]", porosity));
    bool any_present = false;
    for (std::size_t f = 0; f < materials.size(); ++f) {
      if (materials[f] == nullptr) {
        throw std::invalid_argument(
            fmt::format("pressure equilibration: material {} has no model", f));
      }
      if (!(bulk_density[f] >= 0.0 && std::isfinite(bulk_density[f]))) {
        fail(fmt::format("{}: bulk density {} kg/m3 is negative or not finite", name(f),
                         bulk_density[f]));
      }
      if (!(temperature[f] > 0.0 && std::isfinite(temperature[f]))) {
        fail(fmt::format("{}: temperature {} K is not positive and finite", name(f),
                         temperature[f]));
      }
      any_present = any_present || bulk_density[f] > 0.0;
    }
    if (!any_present) fail("no fluid material has a positive bulk density");
  }

  // f(eos) with material f's model as its own type (calls inlined).
  template <class F>
  decltype(auto) model(std::size_t f, F&& function) const {
    return visit_model(*materials_[f], kinds_[f], function);
  }

  std::size_t size() const { return materials_.size(); }
  double porosity() const { return porosity_; }
  bool present(std::size_t f) const { return bulk_density_[f] > 0.0; }
  double minimum_pressure(std::size_t f) const {
    return model(f, [&](const auto& eos) { return eos.minimum_pressure(temperature_[f]); });
  }

  std::string name(std::size_t f) const {
    return fmt::format("material {} ({})", f, materials_[f]->type());
  }

  // sum_f phi_f(P) - n (Tran et al., MPMICE, eq. 43 with the sign flipped)
  // and its derivative in P, -sum_f phi_f kappa_f.
  struct Value {
    double residual;
    double slope;
  };
  Value at(double pressure) const {
    Value value{-porosity_, 0.0};
    for (std::size_t f = 0; f < size(); ++f) {
      if (!present(f)) continue;
      model(f, [&](const auto& eos) {
        const double rho = eos.density(pressure, temperature_[f]);
        const double phi = bulk_density_[f] / rho;
        value.residual += phi;
        value.slope -= phi * eos.compressibility(rho, temperature_[f]);
      });
    }
    return value;
  }

  // rho_f, phi_f and kappa_f at P, written through the per-material outputs.
  template <class Store>
  void state_at(double pressure, Store&& store) const {
    for (std::size_t f = 0; f < size(); ++f) {
      model(f, [&](const auto& eos) {
        const double rho = eos.density(pressure, temperature_[f]);
        store(f, rho, bulk_density_[f] / rho, eos.compressibility(rho, temperature_[f]));
      });
    }
  }

  [[noreturn]] static void fail(const std::string& what) {
    throw PressureEquilibrationError("pressure equilibration: " + what, 0, not_a_number,
                                     not_a_number);
  }

 private:
  std::span<const EquationOfState* const> materials_;
  std::span<const ModelKind> kinds_;
  std::span<const double> bulk_density_;
  std::span<const double> temperature_;
  double porosity_;
};

struct Root {
  double pressure;
  int iterations;
  double residual;
};

void check(const EquilibrationOptions& options) {
  if (!(options.tolerance > 0.0) || options.max_iterations < 0) {
    throw std::invalid_argument(
        fmt::format("pressure equilibration: tolerance {} must be > 0 and "
                    "max_iterations {} >= 0",
                    options.tolerance, options.max_iterations));
  }
}

// The Newton step when it stays inside the bracket (low, high), else
// bisection (or, with no upper bound yet, a step as far above).
double next_pressure(double pressure, double newton, double low, double high) {
  if (newton > low && newton < high) return newton;
  return std::isfinite(high) ? 0.5 * (low + high) : pressure + (pressure - low);
}

// The iteration of solve() below for one cell, as a state: step() takes the
// residual sum phi_f - n and its slope at `pressure` and either accepts it
// (converged: `pressure` is the root; corrected: one last Newton correction,
// uncounted, was inside the bracket and `pressure` is now that corrected
// value, which squares the remaining error and leaves P and sum phi_f - n at
// round-off), gives up (failed) or moves `pressure` on (next). The cells of
// the batched solve run exactly these decisions.
struct NewtonIteration {
  enum Result { converged, corrected, failed, next };

  NewtonIteration(double lowest, double pressure_guess, double n,
                  const EquilibrationOptions& options)
      : low(lowest),
        pressure(std::isfinite(pressure_guess) && pressure_guess > lowest
                     ? pressure_guess
                     : lowest + one_atmosphere),
        porosity(n),
        tolerance(options.tolerance * n),
        max_iterations(options.max_iterations) {}

  Result step(double residual, double slope) {
    return step(residual, slope, porosity, tolerance, max_iterations, pressure, low, high,
                iterations);
  }

  // The same on a state held elsewhere (the batched solve's arrays).
  static Result step(double residual, double slope, double porosity, double tolerance,
                     int max_iterations, double& pressure, double& low, double& high,
                     int& iterations) {
    const double newton = pressure - residual / slope * ((residual + porosity) / porosity);
    if (std::abs(residual) <= tolerance) {
      if (!(newton > low && newton < high)) return converged;
      pressure = newton;
      return corrected;
    }
    if (iterations == max_iterations || !std::isfinite(residual)) return failed;
    (residual > 0.0 ? low : high) = pressure;
    pressure = next_pressure(pressure, newton, low, high);
    ++iterations;
    return next;
  }

  double low;
  double high = std::numeric_limits<double>::infinity();
  double pressure;
  double porosity;
  double tolerance;
  int max_iterations;
  int iterations = 0;
};

// Tran et al., MPMICE, eqs. 42-43, sum_f phi_f(P) = n, solved by Newton's
// method on G(P) = 1 / sum_f phi_f - 1 / n. Both models here have rho_f affine in
// P, so phi_f = rhobar_f / rho_f is the reciprocal of an affine function and
// 1 / sum_f phi_f is a parallel sum of affine functions: exactly linear for
// one material (Newton lands on the root in one step), concave and
// increasing for several (Newton from below climbs to the root
// monotonically; from above it lands below the root, and a landing outside
// the bracket is replaced by bisection; the bracket keeps any other model
// convergent too). The Newton step on G is the one on sum phi_f - n scaled
// by sum phi_f / n.
Root solve(const PoreFilling& cell, double pressure_guess, const EquilibrationOptions& options) {
  double lowest = -std::numeric_limits<double>::infinity();
  double lowest_present = lowest;
  std::size_t bounding = 0;
  for (std::size_t f = 0; f < cell.size(); ++f) {
    const double p_min = cell.minimum_pressure(f);
    if (p_min > lowest) {
      lowest = p_min;
      bounding = f;
    }
    if (cell.present(f)) lowest_present = std::max(lowest_present, p_min);
  }
  if (lowest > lowest_present) {
    // The bound comes from an absent material: the residual there is finite
    // and the pores must still be over-full at it for a root to lie above.
    const double at_bound = cell.at(lowest).residual;
    if (!(at_bound > 0.0)) {
      throw PressureEquilibrationError(
          fmt::format("pressure equilibration: the materials present cannot fill the pores at any "
                      "pressure above {} Pa, where {} (absent) reaches zero density: sum phi_f - n "
                      "= {:.6e}",
                      lowest, cell.name(bounding), at_bound),
          0, lowest, at_bound);
    }
  }

  NewtonIteration newton(lowest, pressure_guess, cell.porosity(), options);
  for (;;) {
    const auto [residual, slope] = cell.at(newton.pressure);
    switch (newton.step(residual, slope)) {
      case NewtonIteration::converged:
        return {newton.pressure, newton.iterations, residual};
      case NewtonIteration::corrected:
        return {newton.pressure, newton.iterations, cell.at(newton.pressure).residual};
      case NewtonIteration::failed:
        throw PressureEquilibrationError(
            fmt::format("pressure equilibration did not converge in {} iteration{}: P = {} Pa, "
                        "sum phi_f - n = {:.6e} (tolerance {:.1e} n), bracket ({}, {}) Pa",
                        newton.iterations, newton.iterations == 1 ? "" : "s", newton.pressure,
                        residual, options.tolerance, newton.low, newton.high),
            newton.iterations, newton.pressure, residual);
      case NewtonIteration::next:
        break;
    }
  }
}

// The batched solve's per-cell path (cells with an absent material, or
// all of them when the batch gives up): PoreFilling and solve() as for one
// cell, the error rethrown with the cell's index.
void equilibrate_one(std::span<const MaterialCells> materials,
                     std::span<const EquationOfState* const> models,
                     std::span<const ModelKind> kinds, std::span<const double> porosity,
                     std::span<const double> pressure_guess, const EquilibrationOptions& options,
                     std::size_t c, EquilibratedCells& result) {
  constexpr std::size_t most = 16;
  const std::size_t count = materials.size();
  std::array<double, most> small_bulk{};
  std::array<double, most> small_temperature{};
  std::vector<double> large_bulk;
  std::vector<double> large_temperature;
  std::span<double> bulk_density(small_bulk.data(), std::min(count, most));
  std::span<double> temperature(small_temperature.data(), std::min(count, most));
  if (count > most) {
    large_bulk.resize(count);
    large_temperature.resize(count);
    bulk_density = large_bulk;
    temperature = large_temperature;
  }
  for (std::size_t f = 0; f < count; ++f) {
    bulk_density[f] = materials[f].bulk_density[c];
    temperature[f] = materials[f].temperature[c];
  }
  const double guess = pressure_guess.empty() ? one_atmosphere : pressure_guess[c];
  try {
    const PoreFilling cell(models, kinds, bulk_density, temperature, porosity[c]);
    const Root root = solve(cell, guess, options);
    result.pressure[c] = root.pressure;
    result.most_iterations = std::max(result.most_iterations, root.iterations);
    cell.state_at(root.pressure, [&](std::size_t f, double rho, double phi, double kappa) {
      result.density[f][c] = rho;
      result.volume_fraction[f][c] = phi;
      result.compressibility[f][c] = kappa;
    });
  } catch (const PressureEquilibrationError& error) {
    throw error.in_cell(c);
  }
}

// PoreFilling::state_at over cells: rho_f, phi_f and kappa_f at each
// cell's pressure (apart, with restrict-qualified outputs, so that the loop
// vectorises).
template <class Model>
void store_state(const Model& eos, std::size_t cells, const double* __restrict pressure,
                 const double* __restrict temperature, const double* __restrict bulk_density,
                 double* __restrict density, double* __restrict fraction,
                 double* __restrict compressibility) {
  for (std::size_t c = 0; c < cells; ++c) {
    const double rho = eos.density(pressure[c], temperature[c]);
    density[c] = rho;
    fraction[c] = bulk_density[c] / rho;
    compressibility[c] = eos.compressibility(rho, temperature[c]);
  }
}

// All cells at once, for the cells whose materials are all present (every
// cell of an ICE run): per Newton round, sum phi_f - n and its slope are
// evaluated material by material over the cells, the models called as their
// own types (inlined; loops the compiler vectorises), and each cell then
// takes NewtonIteration's decision, so every cell gets the operations of
// solve(). The few cells still iterating after the first rounds are
// evaluated one by one. Cells with an absent material go through
// equilibrate_one. Returns false, leaving the result to be recomputed,
// when any input is bad or a cell fails: the cell-by-cell path then reports
// the first failing cell as it always has.
bool equilibrate_batch(std::span<const MaterialCells> materials,
                       std::span<const EquationOfState* const> models,
                       std::span<const ModelKind> kinds, std::span<const double> porosity,
                       std::span<const double> pressure_guess, const EquilibrationOptions& options,
                       EquilibratedCells& result) {
  const std::size_t cells = porosity.size();
  const std::size_t count = materials.size();
  if (count == 0) return false;
  for (const EquationOfState* eos : models) {
    if (eos == nullptr) return false;
  }
  EquilibratedCells::Workspace& w = result.workspace;
  w.active.clear();
  w.one_by_one.clear();
  // PoreFilling's checks, and which cells have every material present.
  for (std::size_t c = 0; c < cells; ++c) {
    if (!(porosity[c] > 0.0 && porosity[c] <= 1.0)) return false;
    bool any_present = false;
    bool all_present = true;
    for (std::size_t f = 0; f < count; ++f) {
      const double rhobar = materials[f].bulk_density[c];
      const double t = materials[f].temperature[c];
      if (!(rhobar >= 0.0 && std::isfinite(rhobar)) || !(t > 0.0 && std::isfinite(t))) {
        return false;
      }
      any_present = any_present || rhobar > 0.0;
      all_present = all_present && rhobar > 0.0;
    }
    if (!any_present) return false;
    (all_present ? w.active : w.one_by_one).push_back(c);
  }
  for (auto* field : {&w.low, &w.high, &w.pressure, &w.residual, &w.slope}) field->resize(cells);
  w.iterations.resize(cells);

  // solve()'s lower bound (every material present: no absent-material
  // test), the bracket's lower end, and the starting point.
  std::fill(w.low.begin(), w.low.end(), -std::numeric_limits<double>::infinity());
  for (std::size_t f = 0; f < count; ++f) {
    const double* t = materials[f].temperature.data();
    double* lowest = w.low.data();
    visit_model_copy(*models[f], [&](const auto& eos) {
      for (std::size_t c = 0; c < cells; ++c) {
        lowest[c] = std::max(lowest[c], eos.minimum_pressure(t[c]));
      }
    });
  }
  for (std::size_t c = 0; c < cells; ++c) {
    const double guess = pressure_guess.empty() ? one_atmosphere : pressure_guess[c];
    const NewtonIteration start(w.low[c], guess, porosity[c], options);
    w.high[c] = start.high;
    w.pressure[c] = start.pressure;
    w.iterations[c] = 0;
  }

  // PoreFilling::at over all cells (contiguous) or the active ones.
  const auto evaluate = [&](bool all) {
    const double* n = porosity.data();
    const double* pressure = w.pressure.data();
    double* residual = w.residual.data();
    double* slope = w.slope.data();
    if (all) {
      for (std::size_t c = 0; c < cells; ++c) {
        residual[c] = -n[c];
        slope[c] = 0.0;
      }
    } else {
      for (const std::size_t c : w.active) {
        residual[c] = -n[c];
        slope[c] = 0.0;
      }
    }
    for (std::size_t f = 0; f < count; ++f) {
      const double* rhobar = materials[f].bulk_density.data();
      const double* t = materials[f].temperature.data();
      visit_model_copy(*models[f], [&](const auto& eos) {
        const auto add = [&](std::size_t c) {
          const double rho = eos.density(pressure[c], t[c]);
          const double phi = rhobar[c] / rho;
          residual[c] += phi;
          slope[c] -= phi * eos.compressibility(rho, t[c]);
        };
        if (all) {
          for (std::size_t c = 0; c < cells; ++c) add(c);
        } else {
          for (const std::size_t c : w.active) add(c);
        }
      });
    }
  };
  while (!w.active.empty()) {
    // While most cells iterate, evaluating every cell costs less than
    // gathering the active ones.
    evaluate(2 * w.active.size() > cells);
    std::size_t still = 0;
    for (const std::size_t c : w.active) {
      const NewtonIteration::Result step = NewtonIteration::step(
          w.residual[c], w.slope[c], porosity[c], options.tolerance * porosity[c],
          options.max_iterations, w.pressure[c], w.low[c], w.high[c], w.iterations[c]);
      if (step == NewtonIteration::failed) return false;
      if (step == NewtonIteration::next) w.active[still++] = c;
    }
    w.active.resize(still);
  }

  // PoreFilling::state_at at each root; the one-by-one cells overwrite theirs.
  result.most_iterations = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    result.pressure[c] = w.pressure[c];
    result.most_iterations = std::max(result.most_iterations, w.iterations[c]);
  }
  for (std::size_t f = 0; f < count; ++f) {
    const double* rhobar = materials[f].bulk_density.data();
    const double* t = materials[f].temperature.data();
    double* density = result.density[f].data();
    double* fraction = result.volume_fraction[f].data();
    double* compressibility = result.compressibility[f].data();
    const double* pressure = w.pressure.data();
    visit_model_copy(*models[f], [&](const auto& eos) {
      store_state(eos, cells, pressure, t, rhobar, density, fraction, compressibility);
    });
  }
  for (const std::size_t c : w.one_by_one) {
    equilibrate_one(materials, models, kinds, porosity, pressure_guess, options, c, result);
  }
  return true;
}

}  // namespace

CellEquilibrium equilibrate_pressure(std::span<const EquationOfState* const> materials,
                                     std::span<const double> bulk_density,
                                     std::span<const double> temperature, double porosity,
                                     double pressure_guess, const EquilibrationOptions& options) {
  check(options);
  std::vector<ModelKind> kinds;
  for (const EquationOfState* eos : materials) {
    kinds.push_back(eos != nullptr ? model_kind(*eos) : ModelKind::other);
  }
  const PoreFilling cell(materials, kinds, bulk_density, temperature, porosity);
  const Root root = solve(cell, pressure_guess, options);

  CellEquilibrium result;
  result.pressure = root.pressure;
  result.iterations = root.iterations;
  result.residual = root.residual;
  result.density.resize(cell.size());
  result.volume_fraction.resize(cell.size());
  result.compressibility.resize(cell.size());
  cell.state_at(root.pressure, [&](std::size_t f, double rho, double phi, double kappa) {
    result.density[f] = rho;
    result.volume_fraction[f] = phi;
    result.compressibility[f] = kappa;
  });
  return result;
}

void equilibrate_pressure(std::span<const MaterialCells> materials,
                          std::span<const double> porosity, std::span<const double> pressure_guess,
                          const EquilibrationOptions& options, EquilibratedCells& result) {
  check(options);
  const std::size_t cells = porosity.size();
  if (!pressure_guess.empty() && pressure_guess.size() != cells) {
    throw std::invalid_argument(fmt::format(
        "pressure equilibration: {} cells but {} pressure guesses", cells, pressure_guess.size()));
  }
  const std::size_t count = materials.size();
  std::vector<const EquationOfState*> models(count);
  std::vector<ModelKind> kinds(count, ModelKind::other);
  for (std::size_t f = 0; f < count; ++f) {
    const MaterialCells& material = materials[f];
    if (material.bulk_density.size() != cells || material.temperature.size() != cells) {
      throw std::invalid_argument(
          fmt::format("pressure equilibration: {} cells but material {} has {} bulk densities and "
                      "{} temperatures",
                      cells, f, material.bulk_density.size(), material.temperature.size()));
    }
    models[f] = material.eos;
    if (material.eos != nullptr) kinds[f] = model_kind(*material.eos);
  }

  result.pressure.resize(cells);
  for (auto* field : {&result.density, &result.volume_fraction, &result.compressibility}) {
    field->resize(count);
    for (auto& values : *field) values.resize(cells);
  }
  result.most_iterations = 0;

  if (!equilibrate_batch(materials, models, kinds, porosity, pressure_guess, options, result)) {
    result.most_iterations = 0;
    for (std::size_t c = 0; c < cells; ++c) {
      equilibrate_one(materials, models, kinds, porosity, pressure_guess, options, c, result);
    }
  }
}

EquilibratedCells equilibrate_pressure(std::span<const MaterialCells> materials,
                                       std::span<const double> porosity,
                                       std::span<const double> pressure_guess,
                                       const EquilibrationOptions& options) {
  EquilibratedCells result;
  equilibrate_pressure(materials, porosity, pressure_guess, options, result);
  return result;
}

// Tran et al., MPMICE, eq. 52
double mixture_compressibility(std::span<const double> volume_fraction,
                               std::span<const double> compressibility) {
  if (volume_fraction.size() != compressibility.size()) {
    throw std::invalid_argument("mixture compressibility: one compressibility per volume fraction");
  }
  double weighted = 0.0;
  double total = 0.0;
  for (std::size_t f = 0; f < volume_fraction.size(); ++f) {
    weighted += volume_fraction[f] * compressibility[f];
    total += volume_fraction[f];
  }
  return weighted / total;
}

}  // namespace ice

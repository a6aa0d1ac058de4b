#include "ice/eos/pressure_equilibration.hpp"

#include <fmt/format.h>

#include <algorithm>
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

  const double tolerance = options.tolerance * cell.porosity();
  double low = lowest;
  double high = std::numeric_limits<double>::infinity();
  double pressure =
      std::isfinite(pressure_guess) && pressure_guess > low ? pressure_guess : low + one_atmosphere;
  for (int iterations = 0;; ++iterations) {
    const auto [residual, slope] = cell.at(pressure);
    const double newton =
        pressure - residual / slope * ((residual + cell.porosity()) / cell.porosity());
    if (std::abs(residual) <= tolerance) {
      // One last Newton correction, uncounted: it squares the remaining
      // error, leaving P and sum phi_f - n at round-off.
      if (!(newton > low && newton < high)) return {pressure, iterations, residual};
      return {newton, iterations, cell.at(newton).residual};
    }
    if (iterations == options.max_iterations || !std::isfinite(residual)) {
      throw PressureEquilibrationError(
          fmt::format("pressure equilibration did not converge in {} iteration{}: P = {} Pa, "
                      "sum phi_f - n = {:.6e} (tolerance {:.1e} n), bracket ({}, {}) Pa",
                      iterations, iterations == 1 ? "" : "s", pressure, residual, options.tolerance,
                      low, high),
          iterations, pressure, residual);
    }
    (residual > 0.0 ? low : high) = pressure;
    pressure = next_pressure(pressure, newton, low, high);
  }
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

  std::vector<double> bulk_density(count);
  std::vector<double> temperature(count);
  for (std::size_t c = 0; c < cells; ++c) {
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

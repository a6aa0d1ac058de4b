#pragma once

#include <cstdint>

#include "ice/eos/equation_of_state.hpp"
#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"

namespace ice {

// The built-in equations of state by their own (final) types, so that loops
// over cells call them directly, inlined, instead of through the virtual
// interface (the pressure equilibration evaluates them per cell and Newton
// iteration). Any other model goes through the interface: same results.
enum class ModelKind : std::uint8_t { linear_water, ideal_gas, other };

inline ModelKind model_kind(const EquationOfState& eos) {
  if (dynamic_cast<const LinearWater*>(&eos) != nullptr) return ModelKind::linear_water;
  if (dynamic_cast<const IdealGas*>(&eos) != nullptr) return ModelKind::ideal_gas;
  return ModelKind::other;
}

// f(model) with `model` the EOS as its final type when `kind` (from
// model_kind(eos)) names one, else as the interface.
template <class F>
decltype(auto) visit_model(const EquationOfState& eos, ModelKind kind, F&& f) {
  switch (kind) {
    case ModelKind::linear_water:
      return f(static_cast<const LinearWater&>(eos));
    case ModelKind::ideal_gas:
      return f(static_cast<const IdealGas&>(eos));
    case ModelKind::other:
      break;
  }
  return f(eos);
}

template <class F>
decltype(auto) visit_model(const EquationOfState& eos, F&& f) {
  return visit_model(eos, model_kind(eos), f);
}

// As visit_model, a built-in model passed as a local copy (a few numbers):
// a loop over cells calling it then knows that its stores leave the
// model's parameters alone, so the compiler neither reloads them per cell
// nor gives up vectorising. For loops over many cells, not per cell.
template <class F>
decltype(auto) visit_model_copy(const EquationOfState& eos, F&& f) {
  switch (model_kind(eos)) {
    case ModelKind::linear_water: {
      const LinearWater model = static_cast<const LinearWater&>(eos);
      return f(model);
    }
    case ModelKind::ideal_gas: {
      const IdealGas model = static_cast<const IdealGas&>(eos);
      return f(model);
    }
    case ModelKind::other:
      break;
  }
  return f(eos);
}

}  // namespace ice

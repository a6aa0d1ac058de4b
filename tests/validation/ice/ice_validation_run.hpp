#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "ice/case/load_case.hpp"
#include "ice/case/make_solver.hpp"

// The case files these validations run, and the time loop of ice_fluid
// (CFL step, growth limit, halving on a rejected step) for tests that look
// at the state between steps.
namespace ice::validation {

inline std::filesystem::path config(const char* name) {
  return std::filesystem::path(COSIM_SOURCE_DIR) / "configs" / "ice" / name;
}

template <int Dim>
void run_until(IceSolver<Dim>& solver, const CaseDescription& c, double end_time,
               const std::function<void(const IceSolver<Dim>&)>& after_step = {}) {
  double dt = c.numerics.initial_time_step;
  while (solver.time() < end_time * (1.0 - 1e-12)) {
    dt = std::min({solver.stable_time_step(c.numerics.cfl, c.numerics.acoustic),
                   c.numerics.max_step_growth * dt, end_time - solver.time()});
    if (c.numerics.max_time_step > 0.0) dt = std::min(dt, c.numerics.max_time_step);
    while (!solver.advance(dt).accepted) {
      dt *= 0.5;
      if (dt < c.numerics.min_time_step) throw std::runtime_error("time step collapsed");
    }
    if (after_step) after_step(solver);
  }
}

}  // namespace ice::validation

#include <gtest/gtest.h>

#include <cmath>

#include "solver_1d_cases.hpp"
#include "swe/numerics/manning_friction.hpp"

namespace {

TEST(Solver1dFriction, UniformFlowDecaysByTheSemiImplicitManningFactor) {
  // Uniform flow on a flat bed with transmissive ends: the flux terms cancel,
  // so each step multiplies the discharge by 1 / (1 + dt g n^2 |u| / h^(4/3))
  // (Zheng et al., eq. 36).
  const std::size_t n = 30;
  swe::Physics p;
  p.manning = 0.1;
  const swe::Boundaries1d open{{swe::BoundaryKind::transmissive, 0.0},
                               {swe::BoundaryKind::transmissive, 0.0}};
  swe::Solver1d s(swe_test::uneven_edges(n, 0.0, 3.0), p, {}, open);
  const double h = 0.2;
  double hu = 0.3;
  s.set_state(std::vector<double>(n, h), std::vector<double>(n, hu), {});
  for (int k = 0; k < 40; ++k) {
    const double dt = s.stable_time_step();
    s.step(dt);
    hu *= swe::manning_factor(h, hu / h, p.gravity, p.manning, dt);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_NEAR(s.depth()[i], h, 1e-14);
      ASSERT_NEAR(s.discharge_x()[i], hu, 1e-14) << "step " << k << " cell " << i;
    }
  }
  EXPECT_LT(hu, 0.3 * 0.9);
}

}  // namespace

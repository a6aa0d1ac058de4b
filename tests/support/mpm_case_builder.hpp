#pragma once

#include <memory>
#include <string>

#include "cosim/config/document.hpp"
#include "mpm/case/case_description.hpp"
#include "mpm/material/material_registry.hpp"

// Small cases of the MPM solver built in code, for its unit tests.
namespace mpm::testing {

inline std::shared_ptr<const Material> material_from_yaml(const std::string& yaml) {
  const auto document = cosim::config::Document::load_string(yaml, "test_material.yaml");
  return make_material(document.root());
}

inline std::shared_ptr<const Material> elastic(double density, double youngs, double poisson,
                                               const std::string& rate = "jaumann") {
  return material_from_yaml("type: linear_elastic\ndensity: " + std::to_string(density) +
                            "\nyoungs_modulus: " + std::to_string(youngs) + "\npoisson_ratio: " +
                            std::to_string(poisson) + "\nobjective_rate: " + rate + "\n");
}

// A grid of `cells` cells of size h from the origin.
inline CaseDescription empty_case(int dimension, std::array<int, 3> cells, double h) {
  CaseDescription c;
  c.dimension = dimension;
  c.grid.origin = Vec3d::Zero();
  c.grid.spacing = Vec3d::Constant(h);
  c.grid.cells = cells;
  c.time.safety_factor = 0.5;
  return c;
}

// A box body [lo, hi] seeded with ppc x ppc (x ppc) points per cell of size h.
inline BodySpec box_body(const std::string& name, int material, int dimension, const Vec3d& lo,
                         const Vec3d& hi, double h, int ppc) {
  BodySpec body;
  body.name = name;
  body.material = material;
  const double d = h / ppc;
  const int nz = dimension == 3 ? static_cast<int>(std::lround((hi[2] - lo[2]) / d)) : 1;
  const int ny = static_cast<int>(std::lround((hi[1] - lo[1]) / d));
  const int nx = static_cast<int>(std::lround((hi[0] - lo[0]) / d));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        Vec3d x(lo[0] + (i + 0.5) * d, lo[1] + (j + 0.5) * d,
                dimension == 3 ? lo[2] + (k + 0.5) * d : 0.0);
        body.positions.push_back(x);
        body.volumes.push_back(dimension == 3 ? d * d * d : d * d);
        body.half_lengths.push_back(Vec3d::Constant(0.5 * d));
      }
  return body;
}

}  // namespace mpm::testing

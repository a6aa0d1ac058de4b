#include "openfoam/io/window_step_means.hpp"

#include <vector>

namespace openfoam {

void average_over_window_steps(const CaseLayout& layout, std::span<const std::string> step_times,
                               FoamFields& end, int dim) {
  const auto components = static_cast<std::size_t>(dim);
  const bool cloud = !end.cloud_momentum.empty();
  for (const std::string& time : step_times) {
    const std::vector<double> p = layout.read_scalar(time, "p");
    for (std::size_t c = 0; c < end.p.size(); ++c) end.p[c] += p[c];
    if (!cloud) continue;
    const std::vector<double> xyz = layout.read_vector(time, "kinematicCloud:UTrans");
    for (std::size_t c = 0; c < end.p.size(); ++c)
      for (std::size_t k = 0; k < components; ++k)
        end.cloud_momentum[c * components + k] += xyz[3 * c + k];
  }
  const double steps = static_cast<double>(step_times.size() + 1);
  for (double& v : end.p) v /= steps;
  for (double& v : end.cloud_momentum) v /= steps;
}

}  // namespace openfoam

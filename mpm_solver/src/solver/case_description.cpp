#include "mpm/case/case_description.hpp"

#include <algorithm>

namespace mpm {

Vec3d TimeSeries::at(double t) const {
  if (time.empty()) return Vec3d::Zero();
  if (t <= time.front()) return value.front();
  if (t >= time.back()) return value.back();
  const auto upper = std::upper_bound(time.begin(), time.end(), t);
  const auto i = static_cast<std::size_t>(upper - time.begin());
  const double s = (t - time[i - 1]) / (time[i] - time[i - 1]);
  return (1.0 - s) * value[i - 1] + s * value[i];
}

const ThermalProperties* thermal_properties(const CaseDescription& description,
                                            const BodySpec& body) {
  if (body.rigid) return body.thermal_override ? &*body.thermal_override : nullptr;
  const auto& thermal =
      description.materials.at(static_cast<std::size_t>(body.material))->thermal();
  return thermal ? &*thermal : nullptr;
}

bool has_thermal_body(const CaseDescription& description) {
  return std::any_of(description.bodies.begin(), description.bodies.end(), [&](const BodySpec& b) {
    return thermal_properties(description, b) != nullptr;
  });
}

double ContactSpec::friction_between(int a, int b) const {
  const auto it = pair_friction.find({std::min(a, b), std::max(a, b)});
  return it == pair_friction.end() ? friction : it->second;
}

}  // namespace mpm

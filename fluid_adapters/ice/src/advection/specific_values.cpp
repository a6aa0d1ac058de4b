#include "ice/advection/specific_values.hpp"

#include <stdexcept>
#include <string>

namespace ice {

void specific_values(std::span<const double> quantity_density, std::span<const double> bulk_density,
                     double empty_density, EmptyCell empty, std::span<double> specific,
                     double per_unit) {
  if (quantity_density.size() != bulk_density.size() || specific.size() != bulk_density.size()) {
    throw std::invalid_argument("specific_values: sizes differ (quantity " +
                                std::to_string(quantity_density.size()) + ", bulk density " +
                                std::to_string(bulk_density.size()) + ", result " +
                                std::to_string(specific.size()) + ")");
  }
  if (!(per_unit > 0.0)) {
    throw std::invalid_argument("specific_values: per_unit must be positive, got " +
                                std::to_string(per_unit));
  }
  const bool keep_previous = empty == EmptyCell::keep_previous;
  for (std::size_t c = 0; c < specific.size(); ++c) {
    specific[c] = bulk_density[c] > empty_density
                      ? quantity_density[c] / (bulk_density[c] * per_unit)
                  : keep_previous ? specific[c]
                                  : 0.0;
  }
}

}  // namespace ice

#include <stdexcept>
#include <string>

#include "accelerator.hpp"
#include "aitken.hpp"
#include "constant_relaxation.hpp"
#include "iqn_ils.hpp"

namespace cosim::acceleration {

std::unique_ptr<Accelerator> make_accelerator(const AccelerationSpec& spec,
                                              std::vector<Block> blocks) {
  auto refuse = [](const std::string& what) {
    throw std::invalid_argument("acceleration: " + what);
  };
  if (blocks.empty()) refuse("no field to accelerate");
  for (const Block& b : blocks)
    if (b.size == 0) refuse("field '" + b.name + "' has no values");
  if (!(spec.relaxation > 0.0 && spec.relaxation <= 1.0))
    refuse("relaxation " + std::to_string(spec.relaxation) + " is outside (0, 1]");
  if (spec.method == Method::iqn_ils && spec.max_columns == 0) refuse("max_columns must be >= 1");
  if (spec.method == Method::iqn_ils && spec.filter != Filter::none &&
      !(spec.filter_limit > 0.0 && spec.filter_limit < 1.0))
    refuse("filter_limit " + std::to_string(spec.filter_limit) + " is outside (0, 1)");
  BlockWeights weights(spec.preconditioner, std::move(blocks), spec.freeze_preconditioner_after);
  switch (spec.method) {
    case Method::constant:
      return std::make_unique<ConstantRelaxation>(spec.relaxation);
    case Method::aitken:
      return std::make_unique<Aitken>(spec.relaxation, std::move(weights));
    case Method::iqn_ils:
      return std::make_unique<IqnIls>(spec, std::move(weights));
  }
  refuse("unknown method");
  return nullptr;
}

}  // namespace cosim::acceleration

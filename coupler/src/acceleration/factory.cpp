#include <fmt/format.h>

#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "acceleration/accelerator.hpp"
#include "aitken.hpp"
#include "constant_relaxation.hpp"
#include "iqn_ils.hpp"

namespace cosim::acceleration {

namespace {

[[noreturn]] void reject(const std::string& setting, const std::string& why) {
  throw std::invalid_argument("acceleration: " + setting + ": " + why);
}

void check_blocks(const std::vector<Block>& blocks) {
  if (blocks.empty()) reject("blocks", "there must be at least one block");
  std::set<std::string> names;
  for (const Block& block : blocks) {
    if (block.size == 0) reject("blocks", "block '" + block.name + "' has size 0");
    if (!names.insert(block.name).second)
      reject("blocks", "block '" + block.name + "' appears twice");
  }
}

// The relaxation lies in (0, upper), or (0, 1] when upper is 1.
void check_relaxation(double relaxation, double upper, const char* range) {
  const bool inside = relaxation > 0.0 && (upper == 1.0 ? relaxation <= upper : relaxation < upper);
  if (!inside) reject("relaxation", fmt::format("{}", relaxation) + " is not in " + range);
}

void check_iqn_ils(const AccelerationSpec& spec) {
  check_relaxation(spec.relaxation, 1.0, "(0, 1]");
  if (spec.max_columns == 0) reject("max_columns", "IQN needs at least one column");
  if (spec.filter != Filter::none && !(spec.filter_limit > 0.0 && spec.filter_limit < 1.0))
    reject("filter_limit", fmt::format("{}", spec.filter_limit) + " is not in (0, 1)");
}

}  // namespace

std::unique_ptr<Accelerator> make_accelerator(const AccelerationSpec& spec,
                                              std::vector<Block> blocks) {
  check_blocks(blocks);
  switch (spec.method) {
    case Method::constant:
      check_relaxation(spec.relaxation, 2.0, "(0, 2)");
      return std::make_unique<ConstantRelaxation>(spec.relaxation, total_size(blocks));
    case Method::aitken:
      check_relaxation(spec.relaxation, 1.0, "(0, 1]");
      return std::make_unique<Aitken>(spec.relaxation, total_size(blocks));
    case Method::iqn_ils:
    case Method::iqn_imvj:
      check_iqn_ils(spec);
      return std::make_unique<IqnIls>(spec, std::move(blocks));
  }
  reject("method", "unknown value " + std::to_string(static_cast<int>(spec.method)));
}

}  // namespace cosim::acceleration

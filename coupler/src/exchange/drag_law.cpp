#include "exchange/drag_law.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <mutex>

#include "builtin_drag_laws.hpp"
#include "cosim/error.hpp"
#include "exchange/drag_parameters.hpp"

namespace cosim::exchange {

namespace {

struct Registry {
  std::mutex mutex;
  std::map<std::string, DragLawFactory> factories{
      {"kozeny_carman", detail::make_kozeny_carman},
      {"forchheimer", detail::make_forchheimer},
      {"beetstra", detail::make_beetstra},
      {"constant", detail::make_constant_drag},
  };
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

void register_drag_law(const std::string& name, DragLawFactory factory) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  r.factories[name] = std::move(factory);
}

std::vector<std::string> drag_law_names() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  for (const auto& [name, factory] : r.factories) names.push_back(name);
  return names;
}

std::unique_ptr<DragLaw> make_drag_law(const YAML::Node& node, const std::string& key_path,
                                       const std::string& file) {
  if (!node.IsDefined() || !node.IsMap()) {
    const YAML::Mark mark = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
    throw InputError(SourceLocation{file, mark.line + 1, mark.column + 1}, key_path,
                     node.IsDefined() ? "expected a map with a key 'law'"
                                      : "missing: a map with a key 'law' is required");
  }
  DragParameters parameters(node, key_path, file);
  const std::string law = parameters.word("law");

  DragLawFactory factory;
  {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    const auto found = r.factories.find(law);
    if (found == r.factories.end()) {
      std::string known;
      for (const auto& [name, f] : r.factories) known += (known.empty() ? "" : ", ") + name;
      parameters.fail("law", fmt::format("unknown drag law '{}' (known: {})", law, known));
    }
    factory = found->second;
  }
  auto result = factory(parameters);
  parameters.finish();
  return result;
}

namespace detail {

BedLengthScale read_bed_length_scale(DragParameters& parameters) {
  const bool grain = parameters.has("grain_size");
  const bool permeability = parameters.has("permeability");
  if (grain == permeability) {
    parameters.fail(grain ? "permeability" : "grain_size",
                    "give exactly one of 'grain_size' [m] and 'permeability' [m^2] (a number or "
                    "'field')");
  }
  const std::string key = grain ? "grain_size" : "permeability";
  BedLengthScale scale{grain, std::nullopt};
  if (!parameters.is_per_cell(key)) scale.value = parameters.positive(key);
  return scale;
}

double checked_cell_value(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0) {
    throw NumericalError(fmt::format("per-cell {} must be finite and > 0, got {}", what, value));
  }
  return value;
}

}  // namespace detail

}  // namespace cosim::exchange

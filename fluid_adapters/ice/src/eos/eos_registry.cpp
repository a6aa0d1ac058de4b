#include "ice/eos/eos_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "cosim/config/closest_key.hpp"
#include "cosim/error.hpp"
#include "ice/eos/ideal_gas.hpp"
#include "ice/eos/linear_water.hpp"

namespace ice {

EosRegistry& EosRegistry::instance() {
  static EosRegistry registry = [] {
    EosRegistry r;
    register_builtin_equations_of_state(r);
    return r;
  }();
  return registry;
}

void register_builtin_equations_of_state(EosRegistry& registry) {
  registry.add(std::string(IdealGas::name), IdealGas::schema(), &IdealGas::make);
  registry.add(std::string(LinearWater::name), LinearWater::schema(), &LinearWater::make);
}

void EosRegistry::add(std::string type, cosim::config::Schema schema, Maker maker) {
  const auto same = [&](const auto& entry) { return entry.first == type; };
  if (std::any_of(entries_.begin(), entries_.end(), same)) {
    throw std::logic_error("equation of state '" + type + "' registered twice");
  }
  entries_.emplace_back(std::move(type), Entry{std::move(schema), std::move(maker)});
}

std::vector<std::string> EosRegistry::types() const {
  std::vector<std::string> names;
  names.reserve(entries_.size());
  for (const auto& entry : entries_) names.push_back(entry.first);
  return names;
}

const cosim::config::Schema& EosRegistry::schema(const std::string& type) const {
  for (const auto& entry : entries_) {
    if (entry.first == type) return entry.second.schema;
  }
  throw cosim::InputError(fmt::format("unknown equation of state '{}'; {}", type,
                                      cosim::config::suggestion(type, types())));
}

std::unique_ptr<EquationOfState> EosRegistry::make(const cosim::config::Node& node) const {
  if (!node.is_map()) {
    node.fail(fmt::format("expected an equation-of-state mapping, got {}", node.describe()));
  }
  const cosim::config::Node type_node = node["type"];
  const auto type = type_node.as<std::string>();
  for (const auto& [name, entry] : entries_) {
    if (name != type) continue;
    entry.schema.validate(node);
    return entry.maker(node);
  }
  type_node.fail(fmt::format("unknown equation of state '{}'; {}", type,
                             cosim::config::suggestion(type, types())));
}

std::string EosRegistry::help() const {
  std::string text;
  for (const auto& [name, entry] : entries_) {
    text += entry.schema.help(fmt::format("eos with type: {}", name));
    text += '\n';
  }
  return text;
}

}  // namespace ice

#include "mpm/material/material_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "cosim/config/closest_key.hpp"
#include "cosim/error.hpp"

namespace mpm {

MaterialRegistry& MaterialRegistry::instance() {
  // Built-in models are added here, explicitly, so that no model depends on
  // a static initialiser surviving the static library's link.
  static MaterialRegistry registry = [] {
    MaterialRegistry r;
    register_builtin_materials(r);
    return r;
  }();
  return registry;
}

void MaterialRegistry::add(std::string type, cosim::config::Schema schema, Maker maker) {
  const auto same = [&](const auto& entry) { return entry.first == type; };
  if (std::any_of(entries_.begin(), entries_.end(), same)) {
    throw std::logic_error("material type '" + type + "' registered twice");
  }
  entries_.emplace_back(std::move(type), Entry{std::move(schema), std::move(maker)});
}

std::vector<std::string> MaterialRegistry::types() const {
  std::vector<std::string> names;
  names.reserve(entries_.size());
  for (const auto& entry : entries_) names.push_back(entry.first);
  return names;
}

const cosim::config::Schema& MaterialRegistry::schema(const std::string& type) const {
  for (const auto& entry : entries_) {
    if (entry.first == type) return entry.second.schema;
  }
  throw cosim::InputError(fmt::format("unknown material type '{}'; {}", type,
                                      cosim::config::suggestion(type, types())));
}

std::unique_ptr<Material> MaterialRegistry::make(const cosim::config::Node& node) const {
  if (!node.is_map()) node.fail(fmt::format("expected a material mapping, got {}", node.describe()));
  const cosim::config::Node type_node = node["type"];
  const auto type = type_node.as<std::string>();
  for (const auto& [name, entry] : entries_) {
    if (name != type) continue;
    entry.schema.validate(node);
    return entry.maker(node);
  }
  type_node.fail(fmt::format("unknown material type '{}'; {}", type,
                             cosim::config::suggestion(type, types())));
}

std::string MaterialRegistry::help() const {
  std::string text;
  for (const auto& [name, entry] : entries_) {
    text += entry.schema.help(fmt::format("materials.<name> with type: {}", name));
    text += '\n';
  }
  return text;
}

}  // namespace mpm

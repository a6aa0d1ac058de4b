#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cosim/config/closest_key.hpp"
#include "cosim/config/node.hpp"
#include "cosim/config/schema.hpp"
#include "cosim/error.hpp"

namespace cosim::config {

// Models selectable by name from a config file, in the spirit of OpenFOAM's
// run-time selection tables. Each model registers its type name, the Schema
// of its parameters (which is also its `--help-config` documentation) and a
// maker. `make` validates the mapping against the schema of the type its
// selector key names (`type`, or e.g. `law` for drag laws) first, so a maker
// only sees well-formed input; physical checks a schema cannot express are
// the maker's, thrown as InputError at the offending key.
template <class Product>
class SelectionTable {
 public:
  using Maker = std::function<std::unique_ptr<Product>(const Node& parameters)>;

  // `what` names the models in messages ("material", "equation of state");
  // `help_title` is the heading of each model's help, with {} for its type;
  // `selector` is the key whose value names the type.
  SelectionTable(std::string what, std::string help_title, std::string selector = "type")
      : what_(std::move(what)),
        help_title_(std::move(help_title)),
        selector_(std::move(selector)) {}

  void add(std::string type, Schema schema, Maker maker) {
    if (find(type) != nullptr)
      throw std::logic_error(fmt::format("{} type '{}' registered twice", what_, type));
    entries_.push_back({std::move(type), std::move(schema), std::move(maker)});
  }

  std::vector<std::string> types() const {
    std::vector<std::string> names;
    names.reserve(entries_.size());
    for (const Entry& entry : entries_) names.push_back(entry.type);
    return names;
  }

  const Schema& schema(const std::string& type) const {
    if (const Entry* entry = find(type)) return entry->schema;
    throw InputError(unknown(type));
  }

  // `node` is the model's mapping including its selector key; the model's
  // schema fills its defaults in before the maker reads it. Unknown types
  // are refused with a did-you-mean suggestion.
  std::unique_ptr<Product> make(const Node& node) const {
    if (!node.is_map()) {
      node.fail(
          fmt::format("expected a mapping with a `{}` key, got {}", selector_, node.describe()));
    }
    const Node type_node = node[selector_];
    const auto type = type_node.as<std::string>();
    const Entry* entry = find(type);
    if (entry == nullptr) type_node.fail(unknown(type));
    entry->schema.validate(node);
    entry->schema.add_defaults(node);
    return entry->maker(node);
  }

  // The help listing of every registered model.
  std::string help() const {
    std::string text;
    for (const Entry& entry : entries_) {
      text += entry.schema.help(fmt::format(fmt::runtime(help_title_), entry.type));
      text += '\n';
    }
    return text;
  }

 private:
  struct Entry {
    std::string type;
    Schema schema;
    Maker maker;
  };

  const Entry* find(const std::string& type) const {
    const auto it = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const Entry& e) { return e.type == type; });
    return it == entries_.end() ? nullptr : &*it;
  }
  std::string unknown(const std::string& type) const {
    return fmt::format("unknown {} '{}'; {}", what_, type, suggestion(type, types()));
  }

  std::string what_;
  std::string help_title_;
  std::string selector_;
  std::vector<Entry> entries_;
};

// The one table of type `Table`, filled by `add_builtins` on first use. The
// built-in models are added there, explicitly, so that none depends on a
// static initialiser surviving a static library's link.
template <class Table>
Table& builtin_table(void (*add_builtins)(Table&)) {
  static Table table = [add_builtins] {
    Table filled;
    add_builtins(filled);
    return filled;
  }();
  return table;
}

}  // namespace cosim::config

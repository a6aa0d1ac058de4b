#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosim/config/schema.hpp"

namespace cosim::config {

struct Schema::Spec {
  enum class Type {
    object,
    number,
    integer,
    boolean,
    string,
    path,
    one_of,
    sequence,
    map_of,
    vector,
    any_of,
    any
  };

  struct Key {
    std::string name;
    std::shared_ptr<const Schema> value;
    bool required = false;
    std::string doc;
  };

  struct Bound {
    double value = 0.0;
    bool inclusive = true;
  };

  Type type = Type::any;
  std::string doc;
  std::string file_kind;  // set for the top mapping of a file

  std::vector<Key> keys;                  // object
  std::vector<std::string> choices;       // one_of
  std::vector<Schema> alternatives;       // any_of
  std::shared_ptr<const Schema> element;  // sequence item, map_of value

  std::optional<Bound> lower;  // number, integer, vector items
  std::optional<Bound> upper;
  bool non_empty = false;   // string, path
  bool must_exist = false;  // path
  std::size_t min_length = 0;
  std::size_t max_length = std::numeric_limits<std::size_t>::max();

  std::string default_shown;
  bool default_is_value = false;  // default_value (filled in), not default_note
  std::string unit;

  const Key* find_key(const std::string& name) const {
    for (const Key& key : keys) {
      if (key.name == name) return &key;
    }
    return nullptr;
  }
};

}  // namespace cosim::config

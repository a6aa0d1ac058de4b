#include "cosim/config/schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "config/schema_spec.hpp"
#include "cosim/config/closest_key.hpp"
#include "cosim/config/document.hpp"
#include "cosim/config/kind.hpp"

namespace cosim::config {

using Type = Schema::Spec::Type;

namespace {

Schema::Spec spec_of(Type type) {
  Schema::Spec spec;
  spec.type = type;
  return spec;
}

std::string bound_text(const Schema::Spec& spec) {
  if (spec.lower && spec.upper) {
    return fmt::format("in {}{}, {}{}", spec.lower->inclusive ? '[' : '(', spec.lower->value,
                       spec.upper->value, spec.upper->inclusive ? ']' : ')');
  }
  if (spec.lower)
    return fmt::format("{} {}", spec.lower->inclusive ? ">=" : ">", spec.lower->value);
  if (spec.upper)
    return fmt::format("{} {}", spec.upper->inclusive ? "<=" : "<", spec.upper->value);
  return {};
}

bool within_bounds(const Schema::Spec& spec, double value) {
  if (spec.lower &&
      (spec.lower->inclusive ? value < spec.lower->value : value <= spec.lower->value)) {
    return false;
  }
  if (spec.upper &&
      (spec.upper->inclusive ? value > spec.upper->value : value >= spec.upper->value)) {
    return false;
  }
  return true;
}

void check_bounds(const Schema::Spec& spec, const Node& node, double value) {
  if (!within_bounds(spec, value)) {
    node.fail(fmt::format("must be {}, got {}", bound_text(spec), node.describe()));
  }
}

void check_length(const Schema::Spec& spec, const Node& node, const char* what) {
  const std::size_t count = node.size();
  if (count >= spec.min_length && count <= spec.max_length) return;
  if (spec.min_length == spec.max_length) {
    node.fail(fmt::format("expected exactly {} {}, got {}", spec.min_length, what, count));
  }
  if (count < spec.min_length) {
    node.fail(fmt::format("expected at least {} {}, got {}", spec.min_length, what, count));
  }
  node.fail(fmt::format("expected at most {} {}, got {}", spec.max_length, what, count));
}

// Which alternatives of an any_of could describe this node at all (a mapping,
// a list or a scalar); the error of the only fitting one is the helpful one.
bool fits_shape(const Schema::Spec& spec, const Node& node) {
  switch (spec.type) {
    case Type::object:
    case Type::map_of:
      return node.is_map();
    case Type::sequence:
    case Type::vector:
      return node.is_sequence();
    case Type::any:
      return true;
    case Type::any_of:
      return std::any_of(spec.alternatives.begin(), spec.alternatives.end(),
                         [&node](const Schema& s) { return fits_shape(s.spec(), node); });
    case Type::number:
    case Type::integer:
    case Type::boolean:
    case Type::string:
    case Type::path:
    case Type::one_of:
      break;
  }
  return node.is_scalar();
}

void validate_object(const Schema::Spec& spec, const Node& node) {
  if (!spec.file_kind.empty()) expect_kind(node, spec.file_kind);
  if (!node.is_map()) node.fail(fmt::format("expected a mapping, got {}", node.describe()));
  for (const auto& [name, value] : node.entries()) {
    const Schema::Spec::Key* key = spec.find_key(name);
    if (key == nullptr) {
      std::vector<std::string> known;
      for (const auto& k : spec.keys) known.push_back(k.name);
      value.fail_at_key(fmt::format("unknown key '{}'; {}", name, suggestion(name, known)));
    }
    key->value->validate(value);
  }
  for (const auto& key : spec.keys) {
    if (key.required && !node.has(key.name)) {
      const std::string path =
          node.key_path().empty() ? key.name : node.key_path() + "." + key.name;
      throw InputError(
          node.location(), path,
          fmt::format("missing required key '{}' ({})", key.name, key.value->summary()));
    }
  }
}

void validate_any_of(const Schema& schema, const Node& node) {
  std::vector<const Schema*> fitting;
  for (const Schema& alternative : schema.spec().alternatives) {
    if (fits_shape(alternative.spec(), node)) fitting.push_back(&alternative);
  }
  if (fitting.size() == 1) return fitting.front()->validate(node);
  for (const Schema* alternative : fitting) {
    try {
      alternative->validate(node);
      return;
    } catch (const InputError&) {
      // try the next alternative
    }
  }
  node.fail(fmt::format("expected {}, got {}", schema.summary(), node.describe()));
}

}  // namespace

Schema::Schema(std::shared_ptr<Spec> spec) : spec_(std::move(spec)) {}

Schema::Spec& Schema::edit() {
  if (spec_.use_count() > 1) spec_ = std::make_shared<Spec>(*spec_);
  return *spec_;
}

Schema Schema::object(std::string doc) {
  Spec spec = spec_of(Type::object);
  spec.doc = std::move(doc);
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema Schema::file(std::string kind, std::string doc) {
  Schema schema = object(std::move(doc));
  schema.required("kind", one_of({kind}), fmt::format("What this file is: always '{}'.", kind));
  schema.edit().file_kind = std::move(kind);
  return schema;
}

Schema& Schema::required(std::string name, Schema value, std::string doc) {
  edit().keys.push_back(
      {std::move(name), std::make_shared<const Schema>(std::move(value)), true, std::move(doc)});
  return *this;
}

Schema& Schema::optional(std::string name, Schema value, std::string doc) {
  edit().keys.push_back(
      {std::move(name), std::make_shared<const Schema>(std::move(value)), false, std::move(doc)});
  return *this;
}

Schema Schema::number() {
  return Schema(std::make_shared<Spec>(spec_of(Type::number)));
}
Schema Schema::integer() {
  return Schema(std::make_shared<Spec>(spec_of(Type::integer)));
}
Schema Schema::boolean() {
  return Schema(std::make_shared<Spec>(spec_of(Type::boolean)));
}
Schema Schema::string() {
  return Schema(std::make_shared<Spec>(spec_of(Type::string)));
}
Schema Schema::path() {
  return Schema(std::make_shared<Spec>(spec_of(Type::path)));
}
Schema Schema::any() {
  return Schema(std::make_shared<Spec>(spec_of(Type::any)));
}

Schema Schema::one_of(std::vector<std::string> choices) {
  Spec spec = spec_of(Type::one_of);
  spec.choices = std::move(choices);
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema Schema::sequence(Schema item) {
  Spec spec = spec_of(Type::sequence);
  spec.element = std::make_shared<const Schema>(std::move(item));
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema Schema::map_of(Schema value) {
  Spec spec = spec_of(Type::map_of);
  spec.element = std::make_shared<const Schema>(std::move(value));
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema Schema::vector(std::size_t min_length, std::size_t max_length) {
  Spec spec = spec_of(Type::vector);
  spec.min_length = min_length;
  spec.max_length = max_length;
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema Schema::any_of(std::vector<Schema> alternatives) {
  Spec spec = spec_of(Type::any_of);
  spec.alternatives = std::move(alternatives);
  return Schema(std::make_shared<Spec>(std::move(spec)));
}

Schema& Schema::positive() {
  edit().lower = Spec::Bound{0.0, false};
  return *this;
}

Schema& Schema::non_negative() {
  edit().lower = Spec::Bound{0.0, true};
  return *this;
}

Schema& Schema::range(double lo, double hi) {
  edit().lower = Spec::Bound{lo, true};
  edit().upper = Spec::Bound{hi, true};
  return *this;
}

Schema& Schema::non_empty() {
  edit().non_empty = true;
  return *this;
}

Schema& Schema::must_exist() {
  edit().must_exist = true;
  return *this;
}

Schema& Schema::length(std::size_t min_length, std::size_t max_length) {
  edit().min_length = min_length;
  edit().max_length = max_length;
  return *this;
}

Schema& Schema::default_value(std::string yaml) {
  edit().default_shown = std::move(yaml);
  edit().default_is_value = true;
  return *this;
}

Schema& Schema::default_note(std::string text) {
  edit().default_shown = std::move(text);
  edit().default_is_value = false;
  return *this;
}

Schema& Schema::unit(std::string si_unit) {
  edit().unit = std::move(si_unit);
  return *this;
}

void Schema::validate(const Node& node) const {
  const Spec& spec = *spec_;
  switch (spec.type) {
    case Type::object:
      validate_object(spec, node);
      return;
    case Type::number:
      check_bounds(spec, node, node.as<double>());
      return;
    case Type::integer:
      check_bounds(spec, node, static_cast<double>(node.as<std::int64_t>()));
      return;
    case Type::boolean:
      node.as<bool>();
      return;
    case Type::string:
      if (node.as<std::string>().empty() && spec.non_empty) node.fail("must not be empty");
      return;
    case Type::path: {
      const std::filesystem::path resolved = node.as_path();
      std::error_code status;
      if (spec.must_exist && !std::filesystem::exists(resolved, status)) {
        node.fail(
            status ? fmt::format("cannot use the path {}: {}", resolved.string(), status.message())
                   : fmt::format("no such file or directory: {}", resolved.string()));
      }
      return;
    }
    case Type::one_of: {
      const std::string chosen = node.as<std::string>();
      if (std::find(spec.choices.begin(), spec.choices.end(), chosen) == spec.choices.end()) {
        node.fail(fmt::format("'{}' is not a valid choice; {}", chosen,
                              suggestion(chosen, spec.choices)));
      }
      return;
    }
    case Type::sequence:
      if (!node.is_sequence()) node.fail(fmt::format("expected a list, got {}", node.describe()));
      check_length(spec, node, "items");
      for (const Node& item : node.items()) spec.element->validate(item);
      return;
    case Type::map_of:
      if (!node.is_map()) node.fail(fmt::format("expected a mapping, got {}", node.describe()));
      check_length(spec, node, "entries");
      for (const auto& entry : node.entries()) spec.element->validate(entry.second);
      return;
    case Type::vector:
      if (!node.is_sequence()) {
        node.fail(fmt::format("expected a list of numbers, got {}", node.describe()));
      }
      check_length(spec, node, "numbers");
      for (const Node& item : node.items()) check_bounds(spec, item, item.as<double>());
      return;
    case Type::any_of:
      validate_any_of(*this, node);
      return;
    case Type::any:
      return;
  }
}

void Schema::add_defaults(const Node& node) const {
  const Spec& spec = *spec_;
  switch (spec.type) {
    case Type::object:
      if (!node.is_map()) return;
      for (const Spec::Key& key : spec.keys) {
        if (auto present = node.find(key.name)) {
          key.value->add_defaults(*present);
          continue;
        }
        const Spec& value = key.value->spec();
        if (key.required || !value.default_is_value) continue;
        YAML::Node document = node.yaml();  // shares the document's tree
        document[key.name] = YAML::Load(value.default_shown);
        key.value->add_defaults(node[key.name]);
      }
      return;
    case Type::sequence:
      if (node.is_sequence())
        for (const Node& item : node.items()) spec.element->add_defaults(item);
      return;
    case Type::map_of:
      if (node.is_map())
        for (const auto& entry : node.entries()) spec.element->add_defaults(entry.second);
      return;
    case Type::any_of:
      for (const Schema& alternative : spec.alternatives) {
        if (!fits_shape(alternative.spec(), node)) continue;
        try {
          alternative.validate(node);
        } catch (const InputError&) {
          continue;
        }
        alternative.add_defaults(node);
        return;
      }
      return;
    default:
      return;
  }
}

namespace {

const Schema* structured(const Schema& schema) {
  const Schema::Spec& spec = schema.spec();
  if (spec.type != Type::any_of) return &schema;
  for (const Schema& alternative : spec.alternatives) {
    if (alternative.spec().type != Type::one_of) return &alternative;
  }
  return &schema;
}

}  // namespace

std::string Schema::default_of(const std::string& key_path) const {
  const Schema* at = this;
  std::size_t start = 0;
  while (start <= key_path.size()) {
    const std::size_t dot = key_path.find('.', start);
    const std::string part =
        key_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    const Spec& spec = structured(*at)->spec();
    const Schema* next = nullptr;
    if ((part == "<name>" && spec.type == Type::map_of) ||
        (part == "[]" && spec.type == Type::sequence)) {
      next = spec.element.get();
    } else if (const Spec::Key* key = spec.find_key(part)) {
      next = key->value.get();
    }
    if (next == nullptr) throw std::out_of_range("no key '" + key_path + "' in the schema");
    at = next;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return at->spec().default_is_value ? at->spec().default_shown : std::string();
}

namespace {

void check_defaults_of(const Schema& schema, const std::string& path) {
  const Schema::Spec& spec = schema.spec();
  if (spec.default_is_value) {
    const std::string name = "default of " + (path.empty() ? std::string("the file") : path);
    try {
      schema.validate(Document::load_string(spec.default_shown + "\n", name).root());
    } catch (const std::exception& error) {
      throw std::logic_error(fmt::format("{} '{}' is refused by its own schema: {}", name,
                                         spec.default_shown, error.what()));
    }
  }
  auto child = [&path](const std::string& part) { return path.empty() ? part : path + "." + part; };
  switch (spec.type) {
    case Type::object:
      for (const auto& key : spec.keys) check_defaults_of(*key.value, child(key.name));
      return;
    case Type::sequence:
      check_defaults_of(*spec.element, path + "[]");
      return;
    case Type::map_of:
      check_defaults_of(*spec.element, child("<name>"));
      return;
    case Type::any_of:
      for (const Schema& alternative : spec.alternatives) check_defaults_of(alternative, path);
      return;
    default:
      return;
  }
}

}  // namespace

void Schema::check_defaults() const {
  check_defaults_of(*this, "");
}

}  // namespace cosim::config

#include <fmt/format.h>

#include <limits>

#include "config/schema_spec.hpp"
#include "cosim/config/schema.hpp"

namespace cosim::config {

using Type = Schema::Spec::Type;

namespace {

constexpr std::size_t unlimited = std::numeric_limits<std::size_t>::max();

std::string bounds_suffix(const Schema::Spec& spec) {
  if (spec.lower && spec.upper) {
    return fmt::format(" in {}{}, {}{}", spec.lower->inclusive ? '[' : '(', spec.lower->value,
                       spec.upper->value, spec.upper->inclusive ? ']' : ')');
  }
  if (spec.lower)
    return fmt::format(" {} {}", spec.lower->inclusive ? ">=" : ">", spec.lower->value);
  if (spec.upper)
    return fmt::format(" {} {}", spec.upper->inclusive ? "<=" : "<", spec.upper->value);
  return {};
}

std::string count_text(const Schema::Spec& spec, const std::string& noun) {
  if (spec.min_length == spec.max_length) return fmt::format("{} {}", spec.min_length, noun);
  if (spec.max_length == unlimited) {
    if (spec.min_length == 0) return noun;
    return fmt::format("at least {} {}", spec.min_length, noun);
  }
  return fmt::format("{} to {} {}", spec.min_length, spec.max_length, noun);
}

std::string quoted_choices(const std::vector<std::string>& choices) {
  std::vector<std::string> quoted;
  for (const auto& choice : choices) quoted.push_back(fmt::format("'{}'", choice));
  return fmt::format("{}", fmt::join(quoted, " | "));
}

bool has_structure(const Schema::Spec& spec) {
  switch (spec.type) {
    case Type::object:
    case Type::sequence:
    case Type::map_of:
      return true;
    case Type::any_of:
      for (const Schema& alternative : spec.alternatives) {
        if (has_structure(alternative.spec())) return true;
      }
      return false;
    default:
      return false;
  }
}

class Listing {
 public:
  explicit Listing(std::string& out) : out_(out) {}

  void entry(const std::string& path, const Schema& value, const std::string& requirement,
             const std::string& doc) {
    const Schema::Spec& spec = value.spec();
    std::string line = fmt::format("  {}  ({}", path, value.summary());
    if (!requirement.empty()) line += "; " + requirement;
    if (!spec.default_shown.empty()) line += "; default: " + spec.default_shown;
    out_ += line + ")\n";
    if (!doc.empty()) out_ += fmt::format("      {}\n", doc);
  }

  void children(const std::string& path, const Schema& schema) {
    const Schema::Spec& spec = schema.spec();
    switch (spec.type) {
      case Type::object:
        for (const auto& key : spec.keys) {
          const std::string key_path = path.empty() ? key.name : path + "." + key.name;
          entry(key_path, *key.value, key.required ? "required" : "optional", key.doc);
          children(key_path, *key.value);
        }
        return;
      case Type::sequence:
        if (has_structure(spec.element->spec())) {
          entry(path + "[]", *spec.element, "", spec.element->spec().doc);
          children(path + "[]", *spec.element);
        }
        return;
      case Type::map_of: {
        const std::string item_path = path.empty() ? "<name>" : path + ".<name>";
        entry(item_path, *spec.element, "", spec.element->spec().doc);
        children(item_path, *spec.element);
        return;
      }
      case Type::any_of:
        for (const Schema& alternative : spec.alternatives) children(path, alternative);
        return;
      default:
        return;
    }
  }

 private:
  std::string& out_;
};

}  // namespace

std::string Schema::summary() const {
  const Spec& spec = *spec_;
  const std::string unit = spec.unit.empty() ? std::string() : " [" + spec.unit + "]";
  switch (spec.type) {
    case Type::object:
      if (!spec.file_kind.empty()) return fmt::format("mapping with kind: {}", spec.file_kind);
      return "mapping";
    case Type::number:
      return "number" + bounds_suffix(spec) + unit;
    case Type::integer:
      return "integer" + bounds_suffix(spec) + unit;
    case Type::boolean:
      return "true | false";
    case Type::string:
      return spec.non_empty ? "non-empty string" : "string";
    case Type::path:
      return spec.must_exist ? "path to an existing file" : "path";
    case Type::one_of:
      return "one of " + quoted_choices(spec.choices);
    case Type::sequence:
      return fmt::format("list of {}: {}", count_text(spec, "items"), spec.element->summary());
    case Type::map_of:
      return fmt::format("mapping of {} names to: {}", count_text(spec, "user-chosen"),
                         spec.element->summary());
    case Type::vector:
      return fmt::format("list of {}{}{}", count_text(spec, "numbers"),
                         bounds_suffix(spec).empty() ? "" : "," + bounds_suffix(spec), unit);
    case Type::any_of: {
      std::vector<std::string> parts;
      for (const Schema& alternative : spec.alternatives) parts.push_back(alternative.summary());
      return fmt::format("{}", fmt::join(parts, ", or "));
    }
    case Type::any:
      break;
  }
  return "any value";
}

std::string Schema::help(const std::string& title) const {
  std::string out = title + "\n" + std::string(title.size(), '=') + "\n";
  if (!spec_->doc.empty()) out += spec_->doc + "\n";
  out += "\nKeys (path  (type; required or optional; default), then what it means):\n";
  Listing(out).children("", *this);
  return out;
}

}  // namespace cosim::config

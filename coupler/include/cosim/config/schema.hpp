#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "cosim/config/node.hpp"

namespace cosim::config {

// The declared shape of a YAML node: the one place a key is documented. It
// validates a document (refusing unknown keys with a suggestion, missing
// required keys, wrong types, impossible values) and prints the
// `--help-config` listing. Schemas are values: modifiers change this copy.
//
//   Schema job = Schema::file("job", "A coupled run.");
//   job.required("end_time", Schema::number().positive().unit("s"), "Simulated end time.")
//      .optional("transport", Schema::one_of({"zmq", "mpi"}).default_value("zmq"),
//                "How fields travel between processes.");
//   job.validate(Document::load_file(f).root());
class Schema {
 public:
  // Mappings with declared keys. `file` is the top of a YAML file: it also
  // declares the required `kind: <kind>` key and checks it first, with
  // expect_kind's message.
  static Schema object(std::string doc = {});
  static Schema file(std::string kind, std::string doc);
  Schema& required(std::string name, Schema value, std::string doc);
  Schema& optional(std::string name, Schema value, std::string doc);

  // Scalars.
  static Schema number();   // finite real
  static Schema integer();  // whole number
  static Schema boolean();
  static Schema string();
  static Schema path();  // a string, resolved from the file's directory
  static Schema one_of(std::vector<std::string> choices);

  // Collections.
  static Schema sequence(Schema item);  // a list of items of one shape
  static Schema map_of(Schema value);   // user-named keys (participants.<name>)
  static Schema vector(std::size_t min_length, std::size_t max_length);  // numbers, e.g. gravity
  static Schema any_of(std::vector<Schema> alternatives);  // `consistent` or `{kernel: ...}`
  static Schema any();                                     // anything; checked by its reader

  // Constraints. Numbers and integers: positive, non_negative, range
  // (inclusive). Strings and paths: non_empty; paths: must_exist.
  // Sequences, maps, vectors: length (inclusive; also for the item count).
  Schema& positive();
  Schema& non_negative();
  Schema& range(double lo, double hi);
  Schema& non_empty();
  Schema& must_exist();
  Schema& length(std::size_t min_length, std::size_t max_length);

  // The value of an optional key when it is absent, written as YAML
  // ("0.99", "zmq", "[]", "{}"): the one place a default is stated.
  // add_defaults puts it into the document, so that readers take every
  // optional key with a default as present (`node.get<double>("key")`) and
  // never state the default again. A mapping's default "{}" fills its keys'
  // defaults in turn.
  Schema& default_value(std::string yaml);
  // Documentation only, for a default the reader derives from other values
  // ("rho |g|", "the file name"): listed, never filled in.
  Schema& default_note(std::string text);
  // The SI unit of a number (documentation).
  Schema& unit(std::string si_unit);

  // Throws the first error found, as an InputError located at the offending
  // node (or, for a missing key, at the mapping that lacks it).
  void validate(const Node& node) const;

  // After validate: adds to the document `node` belongs to every absent
  // optional key that has a default_value, recursively. Added values have no
  // position in the file (an error at one names the key at line 0).
  void add_defaults(const Node& node) const;

  // The default_value of the key at `key_path` ("zmq.scheme"; through
  // mappings, maps of names as "<name>", lists as "[]", and the mapping
  // alternative of an any_of), empty when it has none. Throws
  // std::out_of_range when the schema has no such key.
  std::string default_of(const std::string& key_path) const;

  // Throws std::logic_error naming the key when a default_value is not a
  // value its own schema accepts (a test's check of every schema).
  void check_defaults() const;

  // One entry per key path: type and constraints, unit, required or default,
  // and the doc, e.g. `participants.<name>.config  path, must exist; required`.
  std::string help(const std::string& title) const;

  // One line: `number > 0 [s]`, `one of: zmq | mpi`, `list of mapping`.
  std::string summary() const;

  struct Spec;
  const Spec& spec() const { return *spec_; }

 private:
  explicit Schema(std::shared_ptr<Spec> spec);
  Spec& edit();

  std::shared_ptr<Spec> spec_;
};

}  // namespace cosim::config

#include "cosim/config/schema.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cosim/config/document.hpp"
#include "example_job_schema.hpp"
#include "input_error.hpp"
#include "scratch_directory.hpp"
#include "yaml_text.hpp"

namespace cosim::config {
namespace {

using cosim::testing::input_error_from;
using testing::column_of;
using testing::example_job_schema;
using testing::valid_job_lines;
using testing::yaml_text;

Node root_of(const std::vector<std::string>& lines) {
  return Document::load_string(yaml_text(lines), "job.yaml").root();
}

// The valid job with 1-based line `line` replaced (or removed when empty).
std::vector<std::string> job_with_line(int line, const std::string& replacement) {
  std::vector<std::string> lines = valid_job_lines();
  const auto at = lines.begin() + (line - 1);
  if (replacement.empty()) {
    lines.erase(at);
  } else {
    *at = replacement;
  }
  return lines;
}

struct Expected {
  int line;
  int column;
  std::string key_path;
  std::string text;
};

void expect_refused(const std::vector<std::string>& lines, const Expected& expected) {
  const Schema schema = example_job_schema();
  const InputError error = input_error_from([&] { schema.validate(root_of(lines)); });
  const std::string message = error.what();
  EXPECT_EQ(error.where().file, "job.yaml");
  EXPECT_EQ(error.where().line, expected.line);
  EXPECT_EQ(error.where().column, expected.column);
  EXPECT_EQ(error.key_path(), expected.key_path);
  EXPECT_NE(message.find("job.yaml:" + std::to_string(expected.line) + ":" +
                         std::to_string(expected.column) + ": key '" + expected.key_path + "'"),
            std::string::npos);
  EXPECT_NE(message.find(expected.text), std::string::npos) << "wanted: " << expected.text;
  EXPECT_EQ(error.code(), ExitCode::bad_input);
}

TEST(ConfigSchema, ValidJobPasses) {
  EXPECT_NO_THROW(example_job_schema().validate(root_of(valid_job_lines())));
}

TEST(ConfigSchema, OptionalKeysMayBeLeftOut) {
  EXPECT_NO_THROW(example_job_schema().validate(
      root_of({"kind: job", "name: a", "end_time: 1", "window: 0.1",
               "participants:", "  soil: {executable: mpm_solver, config: a.yaml}"})));
}

TEST(ConfigSchema, UnknownKeySuggestsTheClosestKnownKey) {
  expect_refused(job_with_line(3, "end_tme: 5.0"),
                 {3, 1, "end_tme", "unknown key 'end_tme'; did you mean 'end_time'?"});
}

TEST(ConfigSchema, UnknownKeyWithNothingCloseListsTheKnownKeys) {
  const std::string line = "  soil:  {executable: mpm_solver, config: a.yaml, threads: 4}";
  expect_refused(job_with_line(8, line),
                 {8, column_of(line, "threads"), "participants.soil.threads",
                  "expected one of: executable, config"});
}

TEST(ConfigSchema, MissingRequiredKeyIsLocatedAtTheParentMapping) {
  expect_refused(job_with_line(4, ""), {1, 1, "window", "missing required key 'window'"});
}

TEST(ConfigSchema, MissingNestedKeyIsLocatedAtItsMapping) {
  const std::string line = "  water: {executable: swe_fluid}";
  expect_refused(job_with_line(9, line), {9, column_of(line, "{"), "participants.water.config",
                                          "missing required key 'config' (path)"});
}

TEST(ConfigSchema, WrongTypeIsLocatedAtTheValue) {
  expect_refused(job_with_line(4, "window: fast"),
                 {4, 9, "window", "expected a number, got 'fast'"});
  expect_refused(job_with_line(2, "name: [a, b]"), {2, 7, "name", "expected a string, got a list"});
  auto lines = valid_job_lines();
  lines.erase(lines.begin() + 7, lines.begin() + 9);
  lines[6] = "participants: [soil, water]";
  expect_refused(lines, {7, 15, "participants", "expected a mapping, got a list"});
}

TEST(ConfigSchema, EmptyValueIsLocatedAtItsKey) {
  expect_refused(job_with_line(4, "window:"), {4, 1, "window", "expected a number, got no value"});
}

TEST(ConfigSchema, NegativeValueIsRefused) {
  expect_refused(job_with_line(3, "end_time: -5.0"),
                 {3, 11, "end_time", "must be > 0, got '-5.0'"});
  expect_refused(job_with_line(3, "end_time: 0"), {3, 11, "end_time", "must be > 0"});
}

TEST(ConfigSchema, OutOfRangeValueIsRefused) {
  auto lines = valid_job_lines();
  lines.push_back("relaxation: 1.5");
  expect_refused(lines, {14, 13, "relaxation", "must be in [0, 1], got '1.5'"});
}

TEST(ConfigSchema, FractionalIntegerIsRefused) {
  auto lines = valid_job_lines();
  lines.push_back("max_iterations: 2.5");
  expect_refused(lines, {14, 17, "max_iterations", "expected a whole number"});
  lines.back() = "max_iterations: 0";
  expect_refused(lines, {14, 17, "max_iterations", "must be > 0"});
}

TEST(ConfigSchema, NonBooleanIsRefused) {
  auto lines = valid_job_lines();
  lines.push_back("restart: maybe");
  expect_refused(lines, {14, 10, "restart", "expected true or false, got 'maybe'"});
}

TEST(ConfigSchema, ValueOutsideTheEnumSuggestsTheClosestChoice) {
  expect_refused(job_with_line(5, "transport: zqm"),
                 {5, 12, "transport", "'zqm' is not a valid choice; did you mean 'zmq'?"});
  expect_refused(job_with_line(5, "transport: tcp"),
                 {5, 12, "transport", "expected one of: zmq, mpi"});
}

TEST(ConfigSchema, VectorLengthAndItemsAreChecked) {
  expect_refused(job_with_line(6, "gravity: [0, -9.81, 0, 1]"),
                 {6, 10, "gravity", "expected at most 3 numbers, got 4"});
  expect_refused(job_with_line(6, "gravity: []"),
                 {6, 10, "gravity", "expected at least 1 numbers"});
  expect_refused(job_with_line(6, "gravity: [0, down]"),
                 {6, 14, "gravity[1]", "expected a number, got 'down'"});
  expect_refused(job_with_line(6, "gravity: -9.81"),
                 {6, 10, "gravity", "expected a list of numbers, got '-9.81'"});
}

TEST(ConfigSchema, EmptyMapOfIsRefusedWhenEntriesAreRequired) {
  auto lines = job_with_line(8, "");
  lines.erase(lines.begin() + 7);
  lines[6] = "participants: {}";
  expect_refused(lines, {7, 15, "participants", "expected at least 1 entries, got 0"});
}

TEST(ConfigSchema, ErrorsInsideListItemsNameTheItem) {
  const std::string line = "  - {from: water, to: soil, field: bed_traction}";
  expect_refused(job_with_line(12, line), {12, column_of(line, "{"), "exchange[1].mapping",
                                           "missing required key 'mapping'"});
}

TEST(ConfigSchema, AnyOfReportsTheErrorOfTheAlternativeThatFitsTheShape) {
  const std::string scalar =
      "  - {from: water, to: soil, field: bed_traction, mapping: conservatve}";
  expect_refused(job_with_line(12, scalar),
                 {12, column_of(scalar, "conservatve"), "exchange[1].mapping",
                  "did you mean 'conservative'?"});
  const std::string object =
      "  - {from: water, to: soil, field: bed_traction, mapping: {constraint: consistent, "
      "kernal: gimp}}";
  expect_refused(
      job_with_line(12, object),
      {12, column_of(object, "kernal"), "exchange[1].mapping.kernal", "did you mean 'kernel'?"});
  const std::string valid_object =
      "  - {from: water, to: soil, field: bed_traction, mapping: {constraint: consistent}}";
  EXPECT_NO_THROW(example_job_schema().validate(root_of(job_with_line(12, valid_object))));
}

TEST(ConfigSchema, AnyOfWithNoFittingShapeListsTheAlternatives) {
  expect_refused(job_with_line(13, "momentum_exchange: [water]"),
                 {13, 20, "momentum_exchange", "expected one of 'none', or mapping, got a list"});
  EXPECT_NO_THROW(
      example_job_schema().validate(root_of(job_with_line(13, "momentum_exchange: none"))));
  expect_refused(job_with_line(13, "momentum_exchange: {mesh: water, drag: darcy}"),
                 {13, 40, "momentum_exchange.drag", "expected one of: kozeny_carman, forchheimer"});
}

TEST(ConfigSchema, AnyOfBetweenScalarsTriesEach) {
  Schema schema = Schema::object();
  schema.required("every", Schema::any_of({Schema::number().positive(), Schema::one_of({"never"})}),
                  "Output interval or never.");
  EXPECT_NO_THROW(schema.validate(Document::load_string("every: 0.5\n", "o.yaml").root()));
  EXPECT_NO_THROW(schema.validate(Document::load_string("every: never\n", "o.yaml").root()));
  const InputError error = input_error_from(
      [&] { schema.validate(Document::load_string("every: -1\n", "o.yaml").root()); });
  EXPECT_NE(std::string(error.what()).find("expected number > 0, or one of 'never', got '-1'"),
            std::string::npos);
}

TEST(ConfigSchema, WrongKindIsRefusedFirst) {
  expect_refused(job_with_line(1, "kind: mpm_case"),
                 {1, 7, "kind", "this is a 'mpm_case' file, but a 'job' file is expected here"});
}

TEST(ConfigSchema, MustExistPathIsCheckedRelativeToTheFile) {
  const cosim::testing::ScratchDirectory dir;
  dir.write("mpm/clay.yaml", "kind: mpm_case\n");
  Schema schema = Schema::object();
  schema.required("config", Schema::path().must_exist(), "Solver case.");
  EXPECT_NO_THROW(
      schema.validate(Document::load_string("config: mpm/clay.yaml\n", dir / "job.yaml").root()));
  const InputError error = input_error_from([&] {
    schema.validate(Document::load_string("config: mpm/sand.yaml\n", dir / "job.yaml").root());
  });
  EXPECT_EQ(error.key_path(), "config");
  EXPECT_EQ(error.where().column, 9);
  EXPECT_NE(std::string(error.what()).find((dir / "mpm" / "sand.yaml").string()),
            std::string::npos);
}

TEST(ConfigSchema, EmptyStringIsRefusedWhereANameIsRequired) {
  expect_refused(job_with_line(2, "name: ''"), {2, 7, "name", "must not be empty"});
}

TEST(ConfigSchema, SequenceLengthIsChecked) {
  Schema schema = Schema::object();
  schema.required("points", Schema::sequence(Schema::number()).length(2, 2), "Two ends.");
  const InputError error = input_error_from(
      [&] { schema.validate(Document::load_string("points: [1, 2, 3]\n", "p.yaml").root()); });
  EXPECT_NE(std::string(error.what()).find("expected exactly 2 items, got 3"), std::string::npos);
}

TEST(ConfigSchema, ModifyingACopyLeavesTheOriginalUnchanged) {
  const Schema any_number = Schema::number();
  Schema positive = any_number;
  positive.positive();
  EXPECT_EQ(any_number.summary(), "number");
  EXPECT_EQ(positive.summary(), "number > 0");
}

}  // namespace
}  // namespace cosim::config

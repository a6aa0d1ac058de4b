#include "cosim/config/node.hpp"

#include <gtest/gtest.h>

#include "cosim/config/document.hpp"
#include "input_error.hpp"
#include "yaml_text.hpp"

namespace cosim::config {
namespace {

using cosim::testing::input_error_from;
using testing::column_of;
using testing::yaml_text;

const std::vector<std::string> job_lines{
    "kind: job",                                                 // 1
    "end_time: 5.0",                                             // 2
    "steps: 1e6",                                                // 3
    "restart: yes",                                              // 4
    "gravity: [0, -9.81]",                                       // 5
    "participants:",                                             // 6
    "  soil:  {executable: mpm_solver, config: mpm/clay.yaml}",  // 7
    "  water: {executable: swe_fluid,  config: swe/tank.yaml}",  // 8
    "exchange:",                                                 // 9
    "  - {from: soil, to: water, field: bed_elevation}",         // 10
    "  - {from: water, to: soil, field: bed_traction}",          // 11
    "window:",                                                   // 12
    "label: fast",                                               // 13
};

Node job_root() {
  return Document::load_string(yaml_text(job_lines), "job.yaml").root();
}

TEST(ConfigNode, ConvertsScalarsAndLists) {
  const Node root = job_root();
  EXPECT_DOUBLE_EQ(root["end_time"].as<double>(), 5.0);
  EXPECT_EQ(root["steps"].as<std::int64_t>(), 1000000);
  EXPECT_EQ(root["steps"].as<int>(), 1000000);
  EXPECT_EQ(root["steps"].as<std::size_t>(), 1000000U);
  EXPECT_TRUE(root["restart"].as<bool>());
  EXPECT_EQ(root["gravity"].as<std::vector<double>>(), (std::vector<double>{0.0, -9.81}));
  EXPECT_EQ(root["participants"]["soil"]["executable"].as<std::string>(), "mpm_solver");
}

TEST(ConfigNode, KeyPathsNameMapKeysAndListIndices) {
  const Node root = job_root();
  EXPECT_EQ(root.key_path(), "");
  EXPECT_EQ(root["participants"]["soil"]["config"].key_path(), "participants.soil.config");
  const std::vector<Node> exchange = root["exchange"].items();
  ASSERT_EQ(exchange.size(), 2U);
  EXPECT_EQ(exchange[1]["field"].key_path(), "exchange[1].field");
  EXPECT_EQ(exchange[1]["field"].as<std::string>(), "bed_traction");
}

TEST(ConfigNode, EntriesKeepFileOrder) {
  std::vector<std::string> names;
  for (const auto& [name, participant] : job_root()["participants"].entries()) {
    names.push_back(name);
    EXPECT_EQ(participant.key_path(), "participants." + name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"soil", "water"}));
}

TEST(ConfigNode, LocationsAreOneBasedLineAndColumn) {
  const Node root = job_root();
  const SourceLocation value = root["end_time"].location();
  EXPECT_EQ(value.file, "job.yaml");
  EXPECT_EQ(value.line, 2);
  EXPECT_EQ(value.column, 11);
  const SourceLocation key = root["end_time"].key_location();
  EXPECT_EQ(key.line, 2);
  EXPECT_EQ(key.column, 1);
  const SourceLocation nested = root["participants"]["water"]["config"].location();
  EXPECT_EQ(nested.line, 8);
  EXPECT_EQ(nested.column, column_of(job_lines[7], "swe/tank.yaml"));
}

TEST(ConfigNode, WrongTypeNamesFileLineColumnAndKeyPath) {
  const InputError error = input_error_from([] { job_root()["label"].as<double>(); });
  EXPECT_EQ(error.where().line, 13);
  EXPECT_EQ(error.where().column, 8);
  EXPECT_EQ(error.key_path(), "label");
  EXPECT_STREQ(error.what(), "job.yaml:13:8: key 'label': expected a number, got 'fast'");
}

TEST(ConfigNode, WrongTypeInsideAListNamesTheItem) {
  const InputError error =
      input_error_from([] { job_root()["exchange"].items()[0]["to"].as<int>(); });
  EXPECT_EQ(error.key_path(), "exchange[0].to");
  EXPECT_EQ(error.where().line, 10);
  EXPECT_EQ(error.where().column, column_of(job_lines[9], "water"));
}

TEST(ConfigNode, WholeNumbersMayBeWrittenAsReals) {
  EXPECT_EQ(job_root()["end_time"].as<int>(), 5);
  const Node root = Document::load_string("cells: 1.5\n", "case.yaml").root();
  const InputError error = input_error_from([&] { root["cells"].as<int>(); });
  EXPECT_NE(std::string(error.what()).find("expected a whole number, got '1.5'"),
            std::string::npos);
}

TEST(ConfigNode, NegativeCountIsRefused) {
  const Node root = Document::load_string("particles: -3\n", "case.yaml").root();
  const InputError error = input_error_from([&] { root["particles"].as<std::size_t>(); });
  EXPECT_NE(std::string(error.what()).find("must not be negative"), std::string::npos);
}

TEST(ConfigNode, NonFiniteNumberIsRefused) {
  const Node root = Document::load_string("cfl: .nan\nend_time: .inf\n", "case.yaml").root();
  input_error_from([&] { root["cfl"].as<double>(); });
  const InputError error = input_error_from([&] { root["end_time"].as<double>(); });
  EXPECT_NE(std::string(error.what()).find("finite"), std::string::npos);
}

TEST(ConfigNode, EmptyValueIsLocatedAtItsKey) {
  const InputError error = input_error_from([] { job_root()["window"].as<double>(); });
  EXPECT_EQ(error.where().line, 12);
  EXPECT_EQ(error.where().column, 1);
  EXPECT_NE(std::string(error.what()).find("got no value"), std::string::npos);
}

TEST(ConfigNode, MissingKeyIsLocatedAtTheMappingThatLacksIt) {
  const InputError error =
      input_error_from([] { job_root()["participants"]["soil"]["drag"].as<std::string>(); });
  EXPECT_EQ(error.key_path(), "participants.soil.drag");
  EXPECT_EQ(error.where().line, 7);
  EXPECT_EQ(error.where().column, column_of(job_lines[6], "{"));
  EXPECT_NE(std::string(error.what()).find("missing required key 'drag'"), std::string::npos);
}

TEST(ConfigNode, ListAccessOnAScalarIsRefused) {
  const InputError error = input_error_from([] { job_root()["end_time"].items(); });
  EXPECT_NE(std::string(error.what()).find("expected a list, got '5.0'"), std::string::npos);
}

TEST(ConfigNode, GetReturnsTheFallbackOnlyWhenTheKeyIsAbsent) {
  const Node root = job_root();
  EXPECT_DOUBLE_EQ(root.get("end_time", 1.0), 5.0);
  EXPECT_DOUBLE_EQ(root.get("output_every", 0.05), 0.05);
  EXPECT_EQ(root.get<std::string>("transport", "zmq"), "zmq");
  EXPECT_EQ(root.get("transport", "mpi"), "mpi");
  EXPECT_EQ(root.get("label", "slow"), "fast");
  EXPECT_TRUE(root.has("exchange"));
  EXPECT_FALSE(root.has("transport"));
  EXPECT_FALSE(root.find("transport").has_value());
  input_error_from([&] { root.get("label", 1.0); });
}

TEST(ConfigNode, FailThrowsAtTheNodeAndFailAtKeyAtItsKey) {
  const Node config = job_root()["participants"]["soil"]["config"];
  const InputError at_value = input_error_from([&] { config.fail("no such solver case"); });
  EXPECT_STREQ(at_value.what(),
               ("job.yaml:7:" + std::to_string(column_of(job_lines[6], "mpm/clay.yaml")) +
                ": key 'participants.soil.config': no such solver case")
                   .c_str());
  const InputError at_key = input_error_from([&] { config.fail_at_key("not allowed here"); });
  EXPECT_EQ(at_key.where().column, column_of(job_lines[6], "config"));
}

}  // namespace
}  // namespace cosim::config

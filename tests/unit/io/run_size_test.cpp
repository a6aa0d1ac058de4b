// The size estimate every solver states before its run, and the limit a
// case sets on it: refused with the estimate and the key to raise.
#include "cosim/io/run_size.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "cosim/config/document.hpp"

namespace cosim {
namespace {

using ::testing::HasSubstr;

constexpr double gib = 1024.0 * 1024.0 * 1024.0;

config::Document case_file(const std::string& text) {
  return config::Document::load_string("kind: x_case\ngrid: {cells: [10, 10]}\n" + text,
                                       "case.yaml");
}

RunSize two_counts(const config::Node& root, double particles) {
  RunSize size;
  size.fixed_bytes = 0.1 * gib;
  size.add(
      {"particles", particles, 500.0, std::numeric_limits<std::uint32_t>::max(), root["grid"]});
  size.add({"grid nodes", 20000.0, 1000.0, 1e18, root["grid"]["cells"]});
  return size;
}

TEST(RunSize, SaysItsCountsAndMemory) {
  const auto document = case_file("");
  RunSize size = two_counts(document.root(), 123456.0);
  EXPECT_DOUBLE_EQ(size.memory_bytes(), 0.1 * gib + 123456.0 * 500.0 + 20000.0 * 1000.0);
  EXPECT_EQ(size.describe(), "123 456 particles, 20 000 grid nodes, about 0.2 GiB");
  EXPECT_EQ(size.count("grid nodes"), 20000.0);
  EXPECT_EQ(size.count("cells"), 0.0);
  check_run_size(size, document.root());
  const auto json = size.to_json();
  EXPECT_EQ(json["particles"], 123456.0);
  EXPECT_EQ(json["grid_nodes"], 20000.0);
  EXPECT_DOUBLE_EQ(json["memory_bytes_estimate"].get<double>(), size.memory_bytes());
  EXPECT_DOUBLE_EQ(json["memory_limit_bytes"].get<double>(), RunLimits::default_memory_gib * gib);
  EXPECT_EQ(grouped(7.0), "7");
  EXPECT_EQ(grouped(1234567.0), "1 234 567");
  EXPECT_EQ(grouped(3e20), "3e+20");
  RunSize small;
  small.fixed_bytes = 35e6;
  EXPECT_EQ(small.describe(), "about 33 MiB");
  small.not_included = "the cells of the case";
  EXPECT_EQ(small.describe(), "about 33 MiB without the cells of the case");
}

TEST(RunSize, AboveTheDefaultLimitIsRefusedWithTheEstimateAndTheKey) {
  const auto document = case_file("");
  RunSize size = two_counts(document.root(), 4e9);  // 1.9 TB of particles
  try {
    check_run_size(size, document.root());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "limits.memory_gib");
    EXPECT_EQ(e.where().file, "case.yaml");
    EXPECT_THAT(e.what(), HasSubstr("about 1863 GiB (4 000 000 000 particles, 20 000 grid nodes)"));
    EXPECT_THAT(e.what(), HasSubstr("limit of 8 GiB"));
    EXPECT_THAT(e.what(), HasSubstr("raise limits.memory_gib"));
  }
}

TEST(RunSize, TheCasesLimitRaisesOrLowersIt) {
  const auto raised = case_file("limits: {memory_gib: 4096}\n");
  RunSize size = two_counts(raised.root(), 4e9);
  EXPECT_NO_THROW(check_run_size(size, raised.root()));
  EXPECT_EQ(size.memory_limit_gib, 4096.0);

  const auto lowered = case_file("limits:\n  memory_gib: 0.1\n");
  size = two_counts(lowered.root(), 123456.0);
  try {
    check_run_size(size, lowered.root());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("case.yaml:4:15: key 'limits.memory_gib'"));
    EXPECT_THAT(e.what(), HasSubstr("more than the limit of 0.1 GiB"));
  }
  EXPECT_NO_THROW(run_limits_schema().validate(lowered.root()["limits"]));
  EXPECT_THROW(run_limits_schema().validate(case_file("limits: {memory: 4}\n").root()["limits"]),
               InputError);
  EXPECT_THROW(
      run_limits_schema().validate(case_file("limits: {memory_gib: 0}\n").root()["limits"]),
      InputError);
}

TEST(RunSize, ACountBeyondTheIndicesIsRefusedAtItsKeyWhateverTheLimit) {
  const auto document = case_file("limits: {memory_gib: 1.0e+12}\n");
  RunSize size = two_counts(document.root(), 5e9);
  try {
    check_run_size(size, document.root());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("case.yaml:2:7: key 'grid'"));
    EXPECT_THAT(e.what(), HasSubstr("5 000 000 000 particles, more than the solver's indices hold "
                                    "(4 294 967 295); the run would need about 2328 GiB"));
  }
}

}  // namespace
}  // namespace cosim

// Every program that reads a YAML file refuses the hostile ones under
// tests/data/yaml/ (an alias inside its own anchor, alias bombs, nesting
// without end) with exit 2 and the line, within seconds: no crash, no hang.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "run_process.hpp"

namespace cosim::testing {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

struct HostileFile {
  const char* name;  // under tests/data/yaml/, without .yaml
  int line;          // where the refusal is located
  const char* says;  // a part of the message
};

struct Program {
  const char* name;  // names the test
  std::vector<std::string> (*command)(const fs::path& file, const fs::path& output);
};

std::vector<std::string> solver(const char* executable, const fs::path& file,
                                const fs::path& output) {
  return {binary(executable).string(), "--config", file.string(), "--output", output.string()};
}

const Program programs[] = {
    {"cosim_validate",
     [](const fs::path& file, const fs::path&) -> std::vector<std::string> {
       return {binary("cosim").string(), "validate", file.string()};
     }},
    {"cosim_run",
     [](const fs::path& file, const fs::path& output) -> std::vector<std::string> {
       return {binary("cosim").string(), "run", file.string(), "--output", output.string()};
     }},
    {"cosim_bench",
     [](const fs::path& file, const fs::path& output) -> std::vector<std::string> {
       return {binary("cosim").string(), "bench", file.string(), "--output", output.string()};
     }},
    {"mpm_solver", [](const fs::path& f, const fs::path& o) { return solver("mpm_solver", f, o); }},
    {"ice_fluid", [](const fs::path& f, const fs::path& o) { return solver("ice_fluid", f, o); }},
    {"swe_fluid", [](const fs::path& f, const fs::path& o) { return solver("swe_fluid", f, o); }},
    {"openfoam_adapter",
     [](const fs::path& f, const fs::path& o) { return solver("openfoam_adapter", f, o); }},
};

const HostileFile hostile_files[] = {
    {"cycle_in_list", 4, "alias '*a'"},
    {"cycle_in_map", 6, "alias '*out'"},
    {"cycle_through_merge", 4, "alias '*out'"},
    {"alias_bomb", 9, "nodes"},
    {"merge_bomb", 9, "nodes"},
    {"deep_nesting", 4, "levels"},
    {"deep_aliases", 6, "levels"},
};

void PrintTo(const Program& program, std::ostream* out) {
  *out << program.name;
}
void PrintTo(const HostileFile& file, std::ostream* out) {
  *out << file.name << ".yaml";
}

// Refusing a file takes milliseconds; a crash or an endless expansion is
// what this limit catches (it allows for a loaded CI machine).
constexpr auto time_limit = std::chrono::seconds(5);

class HostileYaml : public ::testing::TestWithParam<std::tuple<Program, HostileFile>> {};

TEST_P(HostileYaml, IsRefusedWithExitTwoAndTheLineWithinSeconds) {
  const auto& [program, file] = GetParam();
  const fs::path input =
      fs::path(COSIM_SOURCE_DIR) / "tests" / "data" / "yaml" / (std::string(file.name) + ".yaml");
  const fs::path dir = fresh_directory(fmt::format("hostile_yaml_{}_{}", program.name, file.name));
  const auto start = std::chrono::steady_clock::now();
  const ProcessResult r = run(program.command(input, dir / "run"), time_limit);
  const auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start);
  ASSERT_FALSE(r.timed_out) << "still running after " << time_limit.count() << " s\n" << r.output;
  EXPECT_EQ(r.exit_code, 2) << "(-1: killed by a signal) after " << seconds.count() << " s\n"
                            << r.output;
  EXPECT_THAT(r.output, HasSubstr(fmt::format("{}:{}:", input.string(), file.line)));
  EXPECT_THAT(r.output, HasSubstr(file.says));
}

INSTANTIATE_TEST_SUITE_P(EveryProgram, HostileYaml,
                         ::testing::Combine(::testing::ValuesIn(programs),
                                            ::testing::ValuesIn(hostile_files)),
                         [](const auto& p) {
                           return std::string(std::get<0>(p.param).name) + "_" +
                                  std::get<1>(p.param).name;
                         });

}  // namespace
}  // namespace cosim::testing

// Fuzzes the YAML loader: mutated copies of every shipped config and of the
// hostile files under tests/data/yaml/ are loaded as a document and as a job,
// as `cosim validate` reads them. Each must load or be refused with a
// cosim::Error, within the hang limit.

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iostream>

#include "cosim/config/document.hpp"
#include "fuzz_run.hpp"
#include "job/job.hpp"
#include "text_files.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

// What YAML's structure is made of, for the mutator to insert whole.
const std::vector<std::string> yaml_tokens{
    "&a ",    "*a",    "&b ",   "*b",    "<<: ", "<<: *a", "<<: [*a, *b]", "[",     "]",
    "{",      "}",     ", ",    ": ",    "- ",   "? ",     "\n",           "\n  ",  "\n    ",
    "\n- ",   "\t",    "#",     "'",     "\"",   "|\n  ",  ">-\n  ",       "---\n", "...\n",
    "!!str ", "!!map", "!!seq", "!tag ", "~",    "null",   "\\u0000",      "\xff",  "%YAML 1.2\n"};

std::vector<std::string> seeds() {
  std::vector<std::string> texts;
  for (const char* folder : {"configs", "tests/data/yaml"})
    for (const fs::path& file : files_under(fs::path(COSIM_SOURCE_DIR) / folder, ".yaml"))
      texts.push_back(read_text(file));
  return texts;
}

// A job file of its own for each test process.
const fs::path& job_file() {
  static const fs::path file = [] {
    const fs::path dir =
        fs::temp_directory_path() / ("cosim_yaml_fuzz_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / "job.yaml";
  }();
  return file;
}

void load(const std::string& text) {
  (void)config::Document::load_string(text, "fuzz.yaml");
  // It is a document: load it as a job too (schema, cross-references).
  {
    std::ofstream out(job_file(), std::ios::binary | std::ios::trunc);
    out << text;
  }
  (void)job::load_job(job_file());
}

FuzzTarget yaml_target() {
  FuzzTarget target;
  target.name = "yaml";
  target.run = load;
  target.seeds = seeds();
  target.tokens = yaml_tokens;
  target.max_size = 1 << 16;
  target.default_executions = 2000;
  return target;
}

TEST(YamlFuzz, SeedsIncludeEveryShippedConfigAndTheHostileFiles) {
  EXPECT_GE(yaml_target().seeds.size(), 90u);
}

TEST(YamlFuzz, MutatedConfigsLoadOrAreRefusedWithoutCrashOrHang) {
  const FuzzTarget target = yaml_target();
  const FuzzReport report = fuzz(target);
  std::cout << report.summary(target.name) << '\n';
  for (const std::string& failure : report.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(report.crashes, 0u);
  EXPECT_EQ(report.hangs, 0u);
  fs::remove_all(job_file().parent_path());
}

}  // namespace
}  // namespace cosim::testing

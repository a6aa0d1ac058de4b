// prepare_output_directory: two runs never mix in one directory. A
// non-empty one is refused untouched; --overwrite clears an earlier run's
// (and nothing else); --resume, and a directory `cosim run` prepared, keep
// what is there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "scratch_directory.hpp"
#include "text_files.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::ScratchDirectory;
using testing::write_text;

// An earlier run: its summary, a snapshot and a nested case directory.
void earlier_run(const fs::path& dir) {
  write_text(dir / "summary.json", "{}");
  write_text(dir / "snapshot_000007.h5", "old");
  write_text(dir / "case" / "processor0" / "0.5" / "U", "old");
}

TEST(OutputDirectory, MissingOrEmptyIsMadeReady) {
  ScratchDirectory scratch;
  prepare_output_directory(scratch / "a" / "b", OutputReuse::refuse);
  EXPECT_TRUE(fs::is_directory(scratch / "a" / "b"));
  prepare_output_directory(scratch / "a" / "b", OutputReuse::refuse);  // empty
  write_text(scratch / "file", "x");
  EXPECT_THROW(prepare_output_directory(scratch / "file", OutputReuse::overwrite), Error);
}

TEST(OutputDirectory, ANonEmptyDirectoryIsRefusedUntouched) {
  ScratchDirectory scratch;
  const fs::path dir = scratch / "run";
  earlier_run(dir);
  try {
    prepare_output_directory(dir, OutputReuse::refuse);
    FAIL() << "refused nothing";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_THAT(e.what(), HasSubstr("is not empty (3 entries: 'case', 'snapshot_000007.h5', "
                                    "'summary.json'); pass --overwrite"));
    EXPECT_THAT(e.what(), ::testing::Not(HasSubstr("--resume")));
  }
  EXPECT_TRUE(fs::exists(dir / "snapshot_000007.h5"));
  try {
    prepare_output_directory(dir, OutputReuse::refuse, {"summary.json"}, true);
    FAIL() << "refused nothing";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("--resume to continue it"));
  }
}

TEST(OutputDirectory, OverwriteClearsAnEarlierRunWhole) {
  ScratchDirectory scratch;
  const fs::path dir = scratch / "run";
  earlier_run(dir);
  prepare_output_directory(dir, OutputReuse::overwrite);
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(OutputDirectory, OverwriteLeavesADirectoryThatIsNoRunsAlone) {
  ScratchDirectory scratch;
  write_text(scratch / "home" / "thesis.tex", "mine");
  EXPECT_THROW(prepare_output_directory(scratch / "home", OutputReuse::overwrite), Error);
  EXPECT_TRUE(fs::exists(scratch / "home" / "thesis.tex"));
}

TEST(OutputDirectory, ResumeAndPreparedKeepWhatIsThere) {
  ScratchDirectory scratch;
  const fs::path dir = scratch / "run";
  earlier_run(dir);
  write_text(dir / "console.log", "the coupler's");
  prepare_output_directory(dir, OutputReuse::resume);
  prepare_output_directory(dir, OutputReuse::prepared);
  EXPECT_TRUE(fs::exists(dir / "snapshot_000007.h5"));
  EXPECT_TRUE(fs::exists(dir / "console.log"));
}

TEST(OutputDirectory, InsideTellsWhatAnOverwriteWouldDelete) {
  ScratchDirectory scratch;
  write_text(scratch / "out" / "case.yaml", "kind: x");
  EXPECT_TRUE(is_inside(scratch / "out" / "case.yaml", scratch / "out"));
  EXPECT_TRUE(is_inside(scratch / "out" / ".." / "out" / "x", scratch / "out"));
  EXPECT_TRUE(is_inside(scratch / "out", scratch / "out"));
  EXPECT_FALSE(is_inside(scratch / "outside.yaml", scratch / "out"));
  EXPECT_FALSE(is_inside(scratch / "out2" / "case.yaml", scratch / "out"));
}

}  // namespace
}  // namespace cosim

#include "checkpoint/manifest.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "cosim/error.hpp"
#include "text_files.hpp"

namespace cosim::checkpoint {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path checkpoint_with_files(const std::string& name) {
  const fs::path dir = fs::path(COSIM_BINARY_DIR) / "test_runs" / "checkpoint_manifest" / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "soil");
  std::ofstream(dir / "coupler.h5") << "coupler state";
  std::ofstream(dir / "soil" / "participant.h5") << "soil state";
  Manifest m;
  m.cosim_version = COSIM_VERSION;
  m.job_name = "slide";
  m.config_hash = "0123456789abcdef";
  m.config_hash_without_ranks = "00000000ffffffff";
  m.participants = {"soil"};
  m.ranks = {{"soil", 2}};
  m.scheme = "explicit";
  m.window = 40;
  m.time = 0.4;
  write_manifest(dir, m);
  return dir;
}

std::string refusal(const fs::path& dir) {
  try {
    (void)read_manifest(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(CheckpointManifest, ListsEveryFileAndReadsBack) {
  const fs::path dir = checkpoint_with_files("round_trip");
  const Manifest m = read_manifest(dir);
  EXPECT_EQ(m.job_name, "slide");
  EXPECT_EQ(m.window, 40u);
  EXPECT_EQ(m.time, 0.4);
  ASSERT_EQ(m.files.size(), 2u);
  EXPECT_EQ(m.files[0].path, "coupler.h5");
  EXPECT_EQ(m.files[0].size, 13u);
  EXPECT_EQ(m.files[1].path, "soil/participant.h5");
  EXPECT_EQ(m.ranks, (std::map<std::string, int>{{"soil", 2}}));
  EXPECT_NO_THROW(check_same_job(m, dir, "slide", "0123456789abcdef", "1111111111111111"));
  EXPECT_THROW(check_same_job(m, dir, "slide", "fedcba9876543210", "1111111111111111"), InputError);
  EXPECT_THROW(check_same_job(m, dir, "other", "0123456789abcdef", "00000000ffffffff"), InputError);
}

// A job whose participants' ranks alone changed is the same job.
TEST(CheckpointManifest, AJobOnOtherRanksIsTheSameJob) {
  const fs::path dir = checkpoint_with_files("other_ranks");
  const Manifest m = read_manifest(dir);
  EXPECT_NO_THROW(check_same_job(m, dir, "slide", "fedcba9876543210", "00000000ffffffff"));
}

TEST(CheckpointManifest, RefusesWhatIsNotTheCheckpointItDescribes) {
  fs::path dir = checkpoint_with_files("truncated");
  std::ofstream(dir / "coupler.h5") << "coupler";
  EXPECT_THAT(refusal(dir), HasSubstr("coupler.h5 has 7 bytes, the manifest says 13 (truncated?)"));

  dir = checkpoint_with_files("changed");
  std::ofstream(dir / "soil" / "participant.h5") << "SOIL state";
  EXPECT_THAT(refusal(dir), HasSubstr("soil/participant.h5 has changed since it was written"));

  dir = checkpoint_with_files("missing");
  fs::remove(dir / "soil" / "participant.h5");
  EXPECT_THAT(refusal(dir), HasSubstr("soil/participant.h5 is missing"));

  dir = checkpoint_with_files("not_json");
  std::ofstream(dir / manifest_file) << "{ not json";
  EXPECT_THAT(refusal(dir), HasSubstr("manifest.json is not JSON"));

  dir = checkpoint_with_files("other_version");
  std::string text = cosim::testing::read_text(dir / manifest_file);
  const auto at = text.find("\"format_version\": 1");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 19, "\"format_version\": 7");
  std::ofstream(dir / manifest_file) << text;
  EXPECT_THAT(refusal(dir), HasSubstr("its format version is 7, this cosim reads version 1"));

  EXPECT_THAT(refusal(dir / "nowhere"), HasSubstr("no such directory"));
}

}  // namespace
}  // namespace cosim::checkpoint

#include "cosim/io/content_hash.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "cosim/error.hpp"
#include "scratch_directory.hpp"

namespace cosim {
namespace {

TEST(ContentHash, MatchesPublishedFnv1a64Vectors) {
  EXPECT_EQ(to_hex16(hash_bytes("")), "cbf29ce484222325");
  EXPECT_EQ(to_hex16(hash_bytes("a")), "af63dc4c8601ec8c");
  EXPECT_EQ(to_hex16(hash_bytes("foobar")), "85944171f73967e8");
  EXPECT_EQ(to_hex16(0x1ULL), "0000000000000001");
}

TEST(ContentHash, StableAcrossCallsAndChunkingAndEqualForFileAndBytes) {
  testing::ScratchDirectory dir;
  const std::string config = "kind: job\nname: dam_break\nend_time: 5.0\nwindow: 1.0e-3\n";
  std::ofstream(dir / "job.yaml", std::ios::binary) << config;
  const std::uint64_t once = hash_file(dir / "job.yaml");
  EXPECT_EQ(hash_file(dir / "job.yaml"), once);
  EXPECT_EQ(hash_bytes(config), once);
  EXPECT_EQ(ContentHash().update(config.substr(0, 7)).update(config.substr(7)).value(), once);
  EXPECT_NE(hash_bytes(config + " "), once);
  EXPECT_EQ(ContentHash().update(config).hex().size(), 16u);
  EXPECT_THROW(hash_file(dir / "absent.yaml"), InputError);
}

}  // namespace
}  // namespace cosim

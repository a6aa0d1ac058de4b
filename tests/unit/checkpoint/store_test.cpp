#include "checkpoint/store.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <vector>

namespace cosim::checkpoint {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(COSIM_BINARY_DIR) / "test_runs" / "checkpoint_store" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(CheckpointStore, ACheckpointAppearsWholeUnderItsNameAndOnlyTheLastAreKept) {
  const fs::path out = scratch("kept");
  Store store(out, 2);
  for (std::size_t w : {5, 10, 15}) {
    const fs::path partial = store.begin(w);
    EXPECT_EQ(partial.filename().string().front(), '.');
    std::ofstream(partial / "coupler.h5") << w;
    EXPECT_FALSE(fs::exists(out / "checkpoints" / fmt::format("window_{:09d}", w)));
    const fs::path final_dir = store.commit(w);
    EXPECT_TRUE(fs::exists(final_dir / "coupler.h5"));
  }
  EXPECT_EQ(entries(out / "checkpoints"),
            (std::vector<std::string>{"window_000000010", "window_000000015"}));
}

TEST(CheckpointStore, AnUnfinishedCheckpointOfAnEarlierAttemptIsReplaced) {
  const fs::path out = scratch("replaced");
  Store store(out, 1);
  std::ofstream(store.begin(3) / "stale") << "left by a run that died";
  const fs::path partial = store.begin(3);
  EXPECT_FALSE(fs::exists(partial / "stale"));
  store.commit(3);
  EXPECT_EQ(entries(out / "checkpoints"), (std::vector<std::string>{"window_000000003"}));
}

}  // namespace
}  // namespace cosim::checkpoint

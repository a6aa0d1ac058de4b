#include "com/private_directory.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

namespace cosim::com {
namespace {

namespace fs = std::filesystem;

// A pid that ran and is gone: a child that exited and was reaped.
pid_t a_dead_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

fs::path scratch(const std::string& name) {
  const fs::path root = fs::temp_directory_path() /
                        ("private_directory_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  return root;
}

void make_owned(const fs::path& dir, long pid, unsigned long long start) {
  fs::create_directories(dir);
  std::ofstream(dir / "owner") << pid << " " << start << "\n";
}

TEST(PrivateDirectory, IsPrivateRecordsItsOwnerAndIsRemovedAtTheEnd) {
  fs::path path;
  {
    const PrivateDirectory dir = PrivateDirectory::create("cosim-unit-test");
    path = dir.path();
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700);
    std::ifstream owner(path / "owner");
    long pid = 0;
    owner >> pid;
    EXPECT_EQ(pid, ::getpid());
  }
  EXPECT_FALSE(fs::exists(path));
}

// Only this user's directories of the prefix whose owner is gone are
// removed: a live owner's, another prefix's, and one without an owner file
// (not one of ours, or being created) stay.
TEST(PrivateDirectory, AbandonedDirectoriesOfDeadOwnersAreRemoved) {
  const fs::path root = scratch("abandoned");
  make_owned(root / "cosim-dead", a_dead_pid(), 12345);
  make_owned(root / "cosim-alive", ::getpid(), 0);  // start time unknown: not judged
  make_owned(root / "other-dead", a_dead_pid(), 12345);
  fs::create_directories(root / "cosim-no-owner");
  EXPECT_EQ(remove_abandoned_directories(root, "cosim"), 1u);
  EXPECT_FALSE(fs::exists(root / "cosim-dead"));
  EXPECT_TRUE(fs::exists(root / "cosim-alive"));
  EXPECT_TRUE(fs::exists(root / "other-dead"));
  EXPECT_TRUE(fs::exists(root / "cosim-no-owner"));
  fs::remove_all(root);
}

// A pid reused by another process: same pid, another start time.
TEST(PrivateDirectory, AReusedPidDoesNotKeepADirectoryAlive) {
  const fs::path root = scratch("reused");
  make_owned(root / "cosim-reused", ::getpid(), 1);  // this process did not start at tick 1
  EXPECT_EQ(remove_abandoned_directories(root, "cosim"), 1u);
  EXPECT_FALSE(fs::exists(root / "cosim-reused"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace cosim::com

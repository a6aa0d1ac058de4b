#pragma once

#include <filesystem>
#include <string>

namespace cosim::com {

// A directory only its owner can enter (mode 0700) under $TMPDIR (or /tmp),
// for ipc endpoints, removed when this object goes. It holds an `owner`
// file (pid and process start time), so that the directories of hubs that
// died without cleaning up (SIGKILL) are recognised and removed by the next
// create(): same user, and their process gone.
class PrivateDirectory {
 public:
  static PrivateDirectory create(const std::string& prefix);
  PrivateDirectory(PrivateDirectory&& other) noexcept;
  PrivateDirectory& operator=(PrivateDirectory&&) = delete;
  PrivateDirectory(const PrivateDirectory&) = delete;
  ~PrivateDirectory();

  const std::filesystem::path& path() const { return path_; }

 private:
  explicit PrivateDirectory(std::filesystem::path path) : path_(std::move(path)) {}
  std::filesystem::path path_;
};

// Removes `<root>/<prefix>-*` directories of this user whose owner process
// no longer runs; returns how many it removed.
std::size_t remove_abandoned_directories(const std::filesystem::path& root,
                                         const std::string& prefix);

}  // namespace cosim::com

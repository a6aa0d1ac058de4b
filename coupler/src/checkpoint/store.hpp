#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

// Where a run's checkpoints live: `<output>/checkpoints/window_<n>/`, each
// written into the hidden `.window_<n>.partial/` first and renamed when
// complete, so that a checkpoint directory that exists is whole; only the
// last `kept` stay (architecture.md §14).
namespace cosim::checkpoint {

class Store {
 public:
  Store(std::filesystem::path output_dir, std::size_t kept);

  // A fresh, empty directory to write window n's checkpoint into, with one
  // sub-directory per participant made by the caller.
  std::filesystem::path begin(std::size_t window);
  // Renames window n's partial directory into place and removes the oldest
  // checkpoints beyond the kept count; returns the final directory.
  std::filesystem::path commit(std::size_t window);

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path partial(std::size_t window) const;
  std::filesystem::path final_directory(std::size_t window) const;

  std::filesystem::path root_;
  std::size_t kept_;
};

}  // namespace cosim::checkpoint

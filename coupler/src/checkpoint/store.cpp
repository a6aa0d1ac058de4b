#include "checkpoint/store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::checkpoint {

namespace fs = std::filesystem;

namespace {

constexpr const char* prefix = "window_";

}  // namespace

Store::Store(fs::path output_dir, std::size_t kept)
    : root_(std::move(output_dir) / "checkpoints"), kept_(std::max<std::size_t>(kept, 1)) {}

fs::path Store::partial(std::size_t window) const {
  return root_ / fmt::format(".{}{:09d}.partial", prefix, window);
}

fs::path Store::final_directory(std::size_t window) const {
  return root_ / fmt::format("{}{:09d}", prefix, window);
}

fs::path Store::begin(std::size_t window) {
  const fs::path dir = partial(window);
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec)
    throw Error(
        ExitCode::internal_error,
        fmt::format("cannot create the checkpoint directory {}: {}", dir.string(), ec.message()));
  return dir;
}

fs::path Store::commit(std::size_t window) {
  const fs::path target = final_directory(window);
  std::error_code ec;
  fs::remove_all(target, ec);
  fs::rename(partial(window), target, ec);
  if (ec)
    throw Error(ExitCode::internal_error,
                fmt::format("cannot rename the checkpoint {} into place: {}",
                            partial(window).string(), ec.message()));
  std::vector<fs::path> checkpoints;
  for (const auto& entry : fs::directory_iterator(root_))
    if (entry.is_directory() && entry.path().filename().string().rfind(prefix, 0) == 0)
      checkpoints.push_back(entry.path());
  std::sort(checkpoints.begin(), checkpoints.end());  // zero-padded: oldest first
  for (std::size_t i = 0; i + kept_ < checkpoints.size(); ++i) fs::remove_all(checkpoints[i], ec);
  return target;
}

}  // namespace cosim::checkpoint

#include "cosim/io/files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "cosim/error.hpp"

namespace cosim {

namespace fs = std::filesystem;

void create_output_directory(const fs::path& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec)
    throw Error(ExitCode::bad_input,
                "cannot create output directory '" + directory.string() + "': " + ec.message());
  if (!fs::is_directory(directory, ec))
    throw Error(ExitCode::bad_input,
                "output path '" + directory.string() + "' exists and is not a directory");
}

void prepare_output_directory(const fs::path& directory, OutputReuse reuse,
                              const std::vector<std::string>& markers, bool resumable) {
  std::error_code ec;
  if (!fs::exists(directory, ec) ||
      (fs::is_directory(directory, ec) && fs::is_empty(directory, ec))) {
    create_output_directory(directory);
    return;
  }
  create_output_directory(directory);  // refuses a file in its place
  if (reuse == OutputReuse::resume || reuse == OutputReuse::prepared) return;
  const auto is_marker = [&](const std::string& name) {
    return std::find(markers.begin(), markers.end(), name) != markers.end();
  };
  bool earlier_run = false;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    names.push_back(entry.path().filename().string());
    earlier_run = earlier_run || is_marker(names.back());
  }
  std::sort(names.begin(), names.end());
  std::string shown;
  for (std::size_t i = 0; i < std::min<std::size_t>(names.size(), 3); ++i)
    shown += (i ? ", '" : "'") + names[i] + "'";
  if (names.size() > 3) shown += ", ...";
  if (reuse == OutputReuse::refuse)
    throw Error(ExitCode::bad_input,
                fmt::format("output directory '{}' is not empty ({} entries: {}); pass --overwrite "
                            "to replace the run it holds, {}or choose another directory",
                            directory.string(), names.size(), shown,
                            resumable ? "--resume to continue it, " : ""));
  if (!earlier_run)
    throw Error(
        ExitCode::bad_input,
        fmt::format("output directory '{}' holds {} but no '{}': it is not an earlier run's "
                    "directory, so --overwrite will not clear it; choose another directory",
                    directory.string(), shown, markers.empty() ? "" : markers.front()));
  for (const auto& name : names) {
    fs::remove_all(directory / name, ec);
    if (ec)
      throw Error(ExitCode::bad_input, fmt::format("--overwrite: cannot remove '{}': {}",
                                                   (directory / name).string(), ec.message()));
  }
}

bool is_inside(const fs::path& path, const fs::path& directory) {
  const fs::path p = fs::weakly_canonical(fs::absolute(path));
  const fs::path d = fs::weakly_canonical(fs::absolute(directory));
  return std::mismatch(d.begin(), d.end(), p.begin(), p.end()).first == d.end();
}

fs::path staging_path(const fs::path& path) {
  return path.parent_path() / ("." + path.filename().string() + ".tmp");
}

void commit_staged_file(const fs::path& staged, const fs::path& target) {
  std::error_code ec;
  fs::rename(staged, target, ec);
  if (ec)
    throw Error(ExitCode::bad_input, "cannot rename '" + staged.string() + "' to '" +
                                         target.string() + "': " + ec.message());
}

void write_file_atomically(const fs::path& path, std::string_view contents) {
  const fs::path staged = staging_path(path);
  std::FILE* file = std::fopen(staged.c_str(), "wb");
  if (file == nullptr)
    throw Error(ExitCode::bad_input,
                "cannot write '" + staged.string() + "': " + std::strerror(errno));
  const bool written = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
  const bool flushed = std::fflush(file) == 0;
  const int saved_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!(written && flushed && closed)) {
    std::error_code ignored;
    fs::remove(staged, ignored);
    throw Error(ExitCode::bad_input,
                "cannot write '" + staged.string() + "': " + std::strerror(saved_errno));
  }
  commit_staged_file(staged, path);
}

}  // namespace cosim

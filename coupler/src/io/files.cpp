#include "cosim/io/files.hpp"

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

#pragma once

#include <filesystem>
#include <string_view>

// File-system helpers for run directories: output that a crash cannot leave
// half-written (DESIGN.md §6: bad input must lose nothing already written).
namespace cosim {

// Creates `directory` and its parents when missing. Throws Error (bad_input:
// the directory usually comes from `--output`) naming the directory when it
// cannot be created or exists as something other than a directory.
void create_output_directory(const std::filesystem::path& directory);

// The hidden sibling `<dir>/.<name>.tmp` that atomic replacements of `path`
// are staged in.
std::filesystem::path staging_path(const std::filesystem::path& path);

// Renames a fully written `staged` file over `target` (atomic on POSIX file
// systems when both are in the same directory). Throws Error naming both.
void commit_staged_file(const std::filesystem::path& staged, const std::filesystem::path& target);

// Writes `contents` to `path` so that a reader, or a process dying midway,
// sees either the previous file or the complete new one, never a mixture.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace cosim

#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

// File-system helpers for run directories: output that a crash cannot leave
// half-written (architecture.md §6: bad input must lose nothing already written).
namespace cosim {

// Creates `directory` and its parents when missing. Throws Error (bad_input:
// the directory usually comes from `--output`) naming the directory when it
// cannot be created or exists as something other than a directory.
void create_output_directory(const std::filesystem::path& directory);

// What a program may do with an output directory that already holds files.
enum class OutputReuse {
  refuse,     // the default: a non-empty directory is an error (nothing is touched)
  overwrite,  // --overwrite: clear the earlier run it holds, then write afresh
  resume,     // --resume (where the program can): keep what is there
  prepared,   // started by `cosim run`: the coupler made the directory and writes into it too
};

// Makes `directory` ready for a run (architecture.md §6; two runs never mix in one
// directory). Missing or empty: created. Non-empty: refused with
// Error(bad_input) naming it and the flags, unless `reuse` says otherwise
// (resume and prepared keep what is there); --overwrite clears it only when
// it holds one of `markers` (files every run of the program writes, such as
// summary.json), so it never empties a directory that is not an earlier
// run's. `resumable`: the refusal also offers --resume.
void prepare_output_directory(const std::filesystem::path& directory, OutputReuse reuse,
                              const std::vector<std::string>& markers = {"summary.json"},
                              bool resumable = false);

// Whether `path` is `directory` or lies inside it, as both resolve now (an
// input that --overwrite of `directory` would delete).
bool is_inside(const std::filesystem::path& path, const std::filesystem::path& directory);

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

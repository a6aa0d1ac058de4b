#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

// The table of contents of a coupled checkpoint (architecture.md §14):
// `manifest.json` in the checkpoint's directory says which job, version and
// window it holds, and lists every file with its size and content hash, so
// that a checkpoint of another job, another version, or with a file missing,
// truncated or changed is refused before anything starts.
namespace cosim::checkpoint {

inline constexpr const char* manifest_kind = "cosim_checkpoint";
inline constexpr std::int64_t format_version = 1;
inline constexpr const char* manifest_file = "manifest.json";

struct FileEntry {
  std::string path;  // relative to the checkpoint's directory
  std::uintmax_t size = 0;
  std::string hash;  // 16 hex digits of the content hash (cosim/io/content_hash.hpp)
};

struct Manifest {
  std::string cosim_version;
  std::string job_name;
  std::string config_hash;                // the job's, which covers its participants' configs
  std::string config_hash_without_ranks;  // empty in a manifest of before it was kept
  std::vector<std::string> participants;
  std::map<std::string, int> ranks;  // each participant's
  std::string scheme;
  std::uint64_t window = 0;  // the last window the checkpoint holds
  double time = 0.0;         // its end [s]
  std::vector<FileEntry> files;
};

// Lists every file under `directory` (but the manifest) with its size and
// hash, and writes the manifest there.
void write_manifest(const std::filesystem::path& directory, Manifest manifest);

// Reads `directory`'s manifest and checks every file it lists; throws
// InputError (exit 2) saying what is wrong: no manifest or not one, another
// format or cosim version, a file missing, of another size or changed.
Manifest read_manifest(const std::filesystem::path& directory);

// Refuses (InputError) a checkpoint of another job than the one with this
// name and config hash; one whose job differed in its participants' ranks
// alone (config_hash_without_ranks) is the same job.
void check_same_job(const Manifest& manifest, const std::filesystem::path& directory,
                    const std::string& job_name, const std::string& config_hash,
                    const std::string& config_hash_without_ranks);

}  // namespace cosim::checkpoint

#include "checkpoint/manifest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cosim/error.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"

namespace cosim::checkpoint {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void refuse(const fs::path& directory, const std::string& why) {
  throw InputError(
      fmt::format("checkpoint {}: {}; it cannot be restarted from", directory.string(), why));
}

std::string contents_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<FileEntry> list_files(const fs::path& directory) {
  std::vector<FileEntry> files;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), directory).generic_string();
    if (relative == manifest_file) continue;
    files.push_back({relative, entry.file_size(), to_hex16(hash_file(entry.path()))});
  }
  std::sort(files.begin(), files.end(),
            [](const FileEntry& a, const FileEntry& b) { return a.path < b.path; });
  return files;
}

}  // namespace

void write_manifest(const fs::path& directory, Manifest m) {
  m.files = list_files(directory);
  json files = json::array();
  for (const FileEntry& f : m.files)
    files.push_back({{"path", f.path}, {"size", f.size}, {"hash", f.hash}});
  const json j{{"kind", manifest_kind},
               {"format_version", format_version},
               {"cosim_version", m.cosim_version},
               {"job",
                {{"name", m.job_name},
                 {"config_hash", m.config_hash},
                 {"config_hash_without_ranks", m.config_hash_without_ranks}}},
               {"participants", m.participants},
               {"ranks", m.ranks},
               {"scheme", m.scheme},
               {"window", m.window},
               {"time_s", m.time},
               {"files", files}};
  write_file_atomically(directory / manifest_file, j.dump(2) + "\n");
}

Manifest read_manifest(const fs::path& directory) {
  const fs::path file = directory / manifest_file;
  if (!fs::is_directory(directory)) refuse(directory, "no such directory");
  if (!fs::exists(file)) refuse(directory, fmt::format("it has no {}", manifest_file));
  Manifest m;
  json j;
  try {
    j = json::parse(contents_of(file));
  } catch (const std::exception& e) {
    refuse(directory, fmt::format("{} is not JSON ({})", manifest_file, e.what()));
  }
  try {
    if (j.at("kind").get<std::string>() != manifest_kind)
      refuse(directory, fmt::format("{} is of kind '{}', not '{}'", manifest_file,
                                    j.at("kind").get<std::string>(), manifest_kind));
    const auto version = j.at("format_version").get<std::int64_t>();
    if (version != format_version)
      refuse(directory, fmt::format("its format version is {}, this cosim reads version {}",
                                    version, format_version));
    m.cosim_version = j.at("cosim_version").get<std::string>();
    m.job_name = j.at("job").at("name").get<std::string>();
    m.config_hash = j.at("job").at("config_hash").get<std::string>();
    m.config_hash_without_ranks = j.at("job").value("config_hash_without_ranks", std::string());
    m.participants = j.at("participants").get<std::vector<std::string>>();
    m.ranks = j.value("ranks", std::map<std::string, int>());
    m.scheme = j.at("scheme").get<std::string>();
    m.window = j.at("window").get<std::uint64_t>();
    m.time = j.at("time_s").get<double>();
    for (const json& f : j.at("files"))
      m.files.push_back({f.at("path").get<std::string>(), f.at("size").get<std::uintmax_t>(),
                         f.at("hash").get<std::string>()});
  } catch (const json::exception& e) {
    refuse(directory,
           fmt::format("{} lacks a key or has a wrong one ({})", manifest_file, e.what()));
  }
  if (m.cosim_version != COSIM_VERSION)
    refuse(directory, fmt::format("it was written by cosim {}, this is cosim {}", m.cosim_version,
                                  COSIM_VERSION));
  for (const FileEntry& f : m.files) {
    const fs::path path = directory / f.path;
    if (!fs::is_regular_file(path)) refuse(directory, fmt::format("{} is missing", f.path));
    const auto size = fs::file_size(path);
    if (size != f.size)
      refuse(directory, fmt::format("{} has {} bytes, the manifest says {} (truncated?)", f.path,
                                    size, f.size));
    if (to_hex16(hash_file(path)) != f.hash)
      refuse(directory, fmt::format("{} has changed since it was written (content hash {}, the "
                                    "manifest says {})",
                                    f.path, to_hex16(hash_file(path)), f.hash));
  }
  return m;
}

void check_same_job(const Manifest& m, const fs::path& directory, const std::string& job_name,
                    const std::string& config_hash, const std::string& config_hash_without_ranks) {
  const bool other_ranks = !m.config_hash_without_ranks.empty() &&
                           m.config_hash_without_ranks == config_hash_without_ranks;
  if (m.job_name != job_name || (m.config_hash != config_hash && !other_ranks))
    refuse(directory,
           fmt::format("it belongs to job '{}' with config hash {}, this is job '{}' with config "
                       "hash {} (the job file, but for its participants' ranks, and every "
                       "participant's config must be unchanged)",
                       m.job_name, m.config_hash, job_name, config_hash));
}

}  // namespace cosim::checkpoint

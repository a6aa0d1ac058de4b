#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

// The last `count` lines of a text file, oldest first, without line endings
// ('\n' or "\r\n"); a final line without a newline counts. Reads only the end
// of the file, so large logs are cheap. Used on error paths (a failed
// participant's log), so a missing or unreadable file gives an empty list
// instead of an exception that would hide the original failure.
std::vector<std::string> tail_lines(const std::filesystem::path& path, std::size_t count);

}  // namespace cosim

#include "cosim/io/tail_lines.hpp"

#include <algorithm>
#include <fstream>

namespace cosim {

namespace {

constexpr std::streamoff block_size = 1 << 14;

void strip_carriage_return(std::string& line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
}

}  // namespace

std::vector<std::string> tail_lines(const std::filesystem::path& path, std::size_t count) {
  std::vector<std::string> lines;
  if (count == 0) return lines;
  std::ifstream in(path, std::ios::binary);
  if (!in) return lines;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size <= 0) return lines;

  // Read blocks backwards until the buffer holds `count` complete lines
  // (count + 1 newlines before the final line's end) or the whole file.
  std::string tail;
  std::streamoff begin = size;
  auto newlines_needed = [&] {
    const bool ends_with_newline = !tail.empty() && tail.back() == '\n';
    return count + (ends_with_newline ? 1 : 0);
  };
  while (begin > 0) {
    const std::streamoff length = std::min(block_size, begin);
    begin -= length;
    std::string block(static_cast<std::size_t>(length), '\0');
    in.seekg(begin);
    if (!in.read(block.data(), length)) return {};
    tail.insert(0, block);
    if (static_cast<std::size_t>(std::count(tail.begin(), tail.end(), '\n')) >= newlines_needed())
      break;
  }

  if (!tail.empty() && tail.back() == '\n') tail.pop_back();
  std::size_t end = tail.size();
  while (lines.size() < count) {
    const std::size_t newline = end == 0 ? std::string::npos : tail.rfind('\n', end - 1);
    const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
    if (newline == std::string::npos && begin > 0) break;  // partial first line: not needed
    lines.push_back(tail.substr(start, end - start));
    strip_carriage_return(lines.back());
    if (newline == std::string::npos) break;
    end = newline;
  }
  std::reverse(lines.begin(), lines.end());
  return lines;
}

}  // namespace cosim

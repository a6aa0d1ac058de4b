#include "cosim/io/content_hash.hpp"

#include <fmt/format.h>

#include <array>
#include <fstream>

#include "cosim/error.hpp"

namespace cosim {

namespace {
constexpr std::uint64_t fnv_prime = 1099511628211ULL;
}

ContentHash& ContentHash::update(std::span<const std::byte> bytes) {
  for (const std::byte b : bytes) {
    state_ ^= static_cast<std::uint64_t>(b);
    state_ *= fnv_prime;
  }
  return *this;
}

ContentHash& ContentHash::update(std::string_view text) {
  return update(std::as_bytes(std::span(text.data(), text.size())));
}

std::string ContentHash::hex() const {
  return to_hex16(state_);
}

std::uint64_t hash_bytes(std::string_view bytes) {
  return ContentHash().update(bytes).value();
}

std::uint64_t hash_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path.string(), 0, 0}, "", "cannot open file to hash it");
  ContentHash hash;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    hash.update(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  }
  if (in.bad())
    throw InputError(SourceLocation{path.string(), 0, 0}, "", "read error while hashing");
  return hash.value();
}

std::string to_hex16(std::uint64_t value) {
  return fmt::format("{:016x}", value);
}

}  // namespace cosim

#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

// Stable 64-bit content hash (FNV-1a) for config files: the same bytes give
// the same value on every platform and run, so summary.json can tell whether
// two runs used the same input.
namespace cosim {

class ContentHash {
 public:
  ContentHash& update(std::span<const std::byte> bytes);
  ContentHash& update(std::string_view text);
  std::uint64_t value() const { return state_; }
  std::string hex() const;

 private:
  static constexpr std::uint64_t offset_basis = 14695981039346656037ULL;
  std::uint64_t state_ = offset_basis;
};

std::uint64_t hash_bytes(std::string_view bytes);
// Hash of the file's bytes; throws InputError naming the file when it cannot be read.
std::uint64_t hash_file(const std::filesystem::path& path);
// Exactly 16 lowercase hex digits, zero-padded.
std::string to_hex16(std::uint64_t value);

}  // namespace cosim

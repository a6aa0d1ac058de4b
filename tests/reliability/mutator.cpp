#include "mutator.hpp"

#include <array>
#include <cstring>

namespace cosim::testing {

namespace {

// Products of two of them (a count times components) reach 2^61 and 2^64,
// where a size in bytes wraps to zero.
constexpr std::array<std::uint64_t, 26> interesting_integers{
    0,
    1,
    2,
    0x7f,
    0x80,
    0xff,
    0x7fff,
    0xffff,
    0x7fffffff,
    0x80000000,
    0xffffffff,
    0x100000000,
    0x100000001,
    (std::uint64_t{1} << 40) - 1,
    std::uint64_t{1} << 40,
    (std::uint64_t{1} << 40) + 1,
    std::uint64_t{1} << 21,
    std::uint64_t{1} << 29,
    std::uint64_t{1} << 24,
    std::uint64_t{1} << 33,
    std::uint64_t{1} << 61,
    0x7fffffffffffffff,
    0x8000000000000000,
    0xfffffffffffffffe,
    0xffffffffffffffff,
    0x2000000000000001,
};

// The same boundaries as a text would write them, and numbers that do not
// fit a double or an int.
const std::array<const char*, 16> interesting_numbers{
    "0",       "-1",    "4294967295", "4294967296",           "18446744073709551615",
    "1e308",   "1e309", "-1e309",     "18446744073709551616", "9223372036854775808",
    ".nan",    ".inf",  "-.inf",      "0x7fffffff",           "1099511627776",
    "2.5e-324"};

}  // namespace

Mutator::Mutator(std::uint64_t seed, std::vector<std::string> tokens,
                 const std::vector<std::string>& corpus)
    : random_(seed), tokens_(std::move(tokens)), corpus_(corpus) {}

std::size_t Mutator::below(std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
}

std::uint64_t Mutator::interesting_integer() {
  return interesting_integers[below(interesting_integers.size())];
}

std::string Mutator::mutate(const std::string& input, std::size_t max_size) {
  std::string data = input;
  const std::size_t count = 1 + below(4);
  for (std::size_t i = 0; i < count; ++i) mutate_once(data);
  if (data.size() > max_size) data.resize(max_size);
  return data;
}

void Mutator::mutate_once(std::string& data) {
  const auto position = [&](std::size_t extra) { return below(data.size() + extra); };
  switch (below(11)) {
    case 0:  // flip a bit
      if (!data.empty()) {
        const std::size_t at = position(0);
        data[at] = static_cast<char>(data[at] ^ (1 << below(8)));
      }
      break;
    case 1:  // a random byte
      if (!data.empty()) data[position(0)] = static_cast<char>(below(256));
      break;
    case 2:  // insert random bytes
      data.insert(position(1), std::string(1 + below(8), static_cast<char>(below(256))));
      break;
    case 3:  // delete a piece
      if (!data.empty()) {
        const std::size_t at = position(0);
        data.erase(at, 1 + below(std::min<std::size_t>(data.size() - at, 64)));
      }
      break;
    case 4:  // repeat a piece
      if (!data.empty()) {
        const std::size_t at = position(0);
        const std::string piece =
            data.substr(at, 1 + below(std::min<std::size_t>(64, data.size() - at)));
        const std::size_t times = 1 + below(8);
        std::string repeated;
        for (std::size_t i = 0; i < times; ++i) repeated += piece;
        data.insert(position(1), repeated);
      }
      break;
    case 5: {  // splice a piece of another input
      const std::string& other = corpus_[below(corpus_.size())];
      if (other.empty()) break;
      const std::size_t from = below(other.size());
      const std::string piece =
          other.substr(from, 1 + below(std::min<std::size_t>(256, other.size() - from)));
      if (below(2) == 0 || data.empty()) {
        data.insert(position(1), piece);
      } else {
        const std::size_t at = position(0);
        data.replace(at, std::min(piece.size(), data.size() - at), piece);
      }
      break;
    }
    case 6: {  // an interesting integer over 1, 2, 4 or 8 bytes, little-endian
      const std::size_t width = std::size_t{1} << below(4);
      if (data.size() < width) break;
      const std::uint64_t value = interesting_integer();
      std::array<char, 8> bytes{};
      for (std::size_t i = 0; i < 8; ++i) bytes[i] = static_cast<char>((value >> (8 * i)) & 0xff);
      std::memcpy(data.data() + below(data.size() - width + 1), bytes.data(), width);
      break;
    }
    case 7:  // an interesting number as text
      data.insert(position(1), interesting_numbers[below(interesting_numbers.size())]);
      break;
    case 8:
    case 9:  // a token
      if (!tokens_.empty()) data.insert(position(1), tokens_[below(tokens_.size())]);
      break;
    case 10:  // cut the end
      if (!data.empty()) data.resize(position(0));
      break;
  }
}

}  // namespace cosim::testing

#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

// A seeded mutation engine for the fuzz drivers: from the same seed it makes
// the same inputs, so that a failure seen once can be seen again.
namespace cosim::testing {

class Mutator {
 public:
  // `tokens`: fragments worth inserting whole (YAML's anchors, aliases,
  // merge keys, brackets, indentation); `corpus`: the inputs splices take
  // their pieces from.
  Mutator(std::uint64_t seed, std::vector<std::string> tokens,
          const std::vector<std::string>& corpus);

  // A copy of `input` changed by one to four mutations: bit flips, random
  // bytes, insertions and deletions, repeats of a piece, splices from
  // another input, interesting integers (as little-endian bytes and as
  // text) and tokens. The result is at most `max_size` bytes.
  std::string mutate(const std::string& input, std::size_t max_size);

  // A uniformly chosen index below `n` (n > 0).
  std::size_t below(std::size_t n);
  // One of the integers decoders get wrong: 0, 1, sign and size boundaries
  // of 8-64 bit integers, counts near 2^32, 2^40 and 2^64.
  std::uint64_t interesting_integer();

 private:
  void mutate_once(std::string& data);

  std::mt19937_64 random_;
  std::vector<std::string> tokens_;
  const std::vector<std::string>& corpus_;
};

}  // namespace cosim::testing

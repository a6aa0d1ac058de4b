#include "operator_cache.hpp"

namespace cosim::cplscheme {

const mapping::Operator& OperatorCache::get(const OperatorKey& key, const Mesh& from,
                                            std::size_t from_version, const Mesh& to,
                                            std::size_t to_version) {
  auto it = entries_.find(key);
  if (it != entries_.end() && it->second.from_version == from_version &&
      it->second.to_version == to_version)
    return it->second.op;
  mapping::Options options;
  options.kernel = key.kernel;
  Entry entry{mapping::build_operator(from, to, key.constraint, options), from_version, to_version};
  ++builds_;
  auto [slot, inserted] = entries_.insert_or_assign(key, std::move(entry));
  return slot->second.op;
}

}  // namespace cosim::cplscheme

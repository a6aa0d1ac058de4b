#pragma once

#include <cstdint>
#include <string>

#include "cosim/config/node.hpp"

namespace cosim::config {

// What every program can walk in a document with its aliases expanded
// (yaml-cpp's aliases share the anchored node, and every walk over the nodes
// visits it again at each alias).
struct ExpansionLimits {
  std::uint64_t nodes = 0;
  int depth = 0;
};

// Reads `text` as parser events, before any node is built, and refuses with
// an InputError located at the alias (or node) concerned: an alias inside
// the node its anchor names (a cycle: the node would contain itself), and a
// document that, with every alias expanded, holds more nodes or nests deeper
// than `limits` (a few lines of aliases can expand to billions of nodes).
// Syntax errors are left to the caller as YAML::ParserException, among them
// a stray token yaml-cpp would read again without end.
void check_expansion(const std::string& text, const SourceFile& source, ExpansionLimits limits);

}  // namespace cosim::config

#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "cosim/config/node.hpp"

namespace cosim::config {

// One YAML file, parsed. Loading refuses, with an InputError naming the file
// and line:column: a missing or unreadable file, YAML syntax errors, an
// empty file, several documents in one file, duplicate keys, keys that are
// not plain scalars, an alias inside the node its anchor names (the node
// would contain itself), and a document beyond the limits below.
class Document {
 public:
  // A document with every alias expanded (each alias counts its anchor's
  // nodes again: every walk over the nodes visits them again) holds at most
  // this many nodes and nests at most this deep. The largest shipped config
  // holds 1649 nodes and nests 11 levels; an alias bomb of a few lines
  // ("billion laughs") would hold billions.
  static constexpr std::uint64_t max_expanded_nodes = 1'000'000;
  static constexpr int max_depth = 100;

  static Document load_file(const std::filesystem::path& file);
  // `name` stands for the file in messages; relative paths in the text
  // resolve from its directory (the working directory if it has none).
  static Document load_string(std::string_view text, const std::filesystem::path& name);

  Node root() const;
  const std::filesystem::path& path() const { return source_->name; }
  const std::filesystem::path& directory() const { return source_->directory; }
  // The text as read, e.g. for a config hash in summary.json.
  const std::string& text() const { return text_; }

 private:
  Document(std::string text, std::shared_ptr<const SourceFile> source, YAML::Node root);

  std::string text_;
  std::shared_ptr<const SourceFile> source_;
  YAML::Node root_;
};

}  // namespace cosim::config

#include "bench/input_file.hpp"

#include <fmt/format.h>

#include <cctype>

#include "cosim/config/document.hpp"
#include "cosim/io/files.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

namespace {

bool is_index(const std::string& part) {
  return !part.empty() && std::all_of(part.begin(), part.end(),
                                      [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::vector<std::string> split_key_path(const std::string& key_path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const auto dot = key_path.find('.', start);
    parts.push_back(key_path.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

}  // namespace

InputFile InputFile::read(const fs::path& file) {
  const auto doc = config::Document::load_file(file);
  InputFile f;
  f.source_ = fs::absolute(file);
  f.root_ = YAML::Clone(doc.root().yaml());
  f.absolutize(f.root_, {});
  return f;
}

InputFile InputFile::from_node(YAML::Node root, std::string role_name) {
  InputFile f;
  f.source_ = role_name;
  f.root_ = std::move(root);
  return f;
}

// A string naming an existing file or directory relative to the original is
// rewritten to its absolute path; `name` keys are names, never paths.
void InputFile::absolutize(YAML::Node node, const std::string& key) {
  if (node.IsMap()) {
    for (auto entry : node) absolutize(entry.second, entry.first.Scalar());
    return;
  }
  if (node.IsSequence()) {
    for (auto item : node) absolutize(item, key);
    return;
  }
  if (!node.IsScalar() || key == "name" || key == "kind") return;
  const std::string text = node.Scalar();
  if (text.empty() || text.front() == '/' || text.size() > 4096) return;
  std::error_code ec;
  const fs::path candidate = source_.parent_path() / text;
  if (!fs::exists(candidate, ec)) return;
  const fs::path absolute = fs::weakly_canonical(candidate, ec);
  node = absolute.string();
  if (fs::is_regular_file(absolute, ec)) referenced_.insert(absolute);
}

void InputFile::apply(const Override& o) {
  const auto parts = split_key_path(o.key_path);
  std::vector<YAML::Node> path{root_};
  std::string walked;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    YAML::Node here = path.back();
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    if (here.IsSequence()) {
      if (!is_index(part) || std::stoul(part) >= here.size())
        throw InputError(o.where, o.key_path,
                         fmt::format("'{}' in {} is a list of {} items; '{}' is not an index of it",
                                     walked, source_.string(), here.size(), part));
      if (last) {
        here[std::stoul(part)] = YAML::Clone(o.value);
        return;
      }
      path.push_back(here[std::stoul(part)]);
    } else {
      if (!(here.IsMap() || here.IsNull()))
        throw InputError(
            o.where, o.key_path,
            fmt::format("'{}' in {} is a value, not a mapping", walked, source_.string()));
      if (last) {
        here[part] = YAML::Clone(o.value);
        return;
      }
      // yaml-cpp's Node::operator= rebinds shared storage: nodes are only
      // ever copy-constructed here.
      if (!here[part].IsDefined() || here[part].IsNull())
        here[part] = YAML::Node(YAML::NodeType::Map);
      path.push_back(here[part]);
    }
    walked += (walked.empty() ? "" : ".") + part;
  }
}

void InputFile::apply_all(const std::vector<Override>& overrides, const std::string& role) {
  for (const auto& o : overrides)
    if (o.role == role) apply(o);
}

std::string InputFile::text() const {
  YAML::Emitter out;
  out << root_;
  return std::string(out.c_str()) + "\n";
}

void InputFile::write(const fs::path& path) const {
  write_file_atomically(path, text());
}

std::string scalar_at(const YAML::Node& root, const std::string& key_path,
                      const std::string& fallback) {
  std::vector<YAML::Node> chain{root};
  for (const auto& part : split_key_path(key_path)) {
    const YAML::Node& node = chain.back();
    if (node.IsSequence() && is_index(part) && std::stoul(part) < node.size()) {
      chain.push_back(node[std::stoul(part)]);
    } else if (node.IsMap() && node[part]) {
      chain.push_back(node[part]);
    } else {
      return fallback;
    }
  }
  return chain.back().IsScalar() ? chain.back().Scalar() : fallback;
}

}  // namespace cosim::bench

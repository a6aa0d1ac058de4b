#include "cosim/config/document.hpp"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>
#include <unordered_map>

#include "expansion_check.hpp"

namespace cosim::config {

namespace {

std::string joined(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

// yaml-cpp gives an alias the very node its anchor names, so a walk over the
// document meets that node again at each alias; the walks below visit each
// sequence and mapping once (a million-node expansion took 1-2 s to walk
// under the sanitizers). yaml-cpp shows a node's identity only through
// Node::is(), hence the lookup by position in the text first.
class Visits {
 public:
  bool first(const YAML::Node& node) {
    if (!node.IsSequence() && !node.IsMap()) return true;
    const auto [begin, end] = seen_.equal_range(node.Mark().pos);
    for (auto it = begin; it != end; ++it)
      if (it->second.is(node)) return false;
    seen_.emplace(node.Mark().pos, node);
    return true;
  }

 private:
  std::unordered_multimap<int, YAML::Node> seen_;
};

// yaml-cpp keeps the last of two equal keys without a word; a config that
// says the same thing twice is a mistake the user must see.
void refuse_duplicate_keys(const YAML::Node& node, const SourceFile& source,
                           const std::string& key_path, Visits& visits) {
  if (!visits.first(node)) return;
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      refuse_duplicate_keys(node[i], source, fmt::format("{}[{}]", key_path, i), visits);
    }
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, YAML::Mark> seen;
  for (const auto& entry : node) {
    const YAML::Node key = entry.first;
    if (!key.IsScalar()) {
      throw InputError(location_in(source, key.Mark()), key_path,
                       "a mapping key must be a plain name, not a list or mapping");
    }
    const std::string path = joined(key_path, key.Scalar());
    auto [first, inserted] = seen.emplace(key.Scalar(), key.Mark());
    if (!inserted) {
      throw InputError(location_in(source, key.Mark()), path,
                       fmt::format("duplicate key; first given at line {}",
                                   location_in(source, first->second).line));
    }
    refuse_duplicate_keys(entry.second, source, path, visits);
  }
}

// YAML's merge key (`<<: *anchor`), which yaml-cpp leaves as a plain key:
// the anchored mapping's entries (or those of a list of mappings, the first
// winning) are added where the mapping does not give them itself.
void expand_merge_keys(YAML::Node node, const SourceFile& source, Visits& visits) {
  if (!visits.first(node)) return;
  if (node.IsSequence()) {
    for (auto item : node) expand_merge_keys(item, source, visits);
    return;
  }
  if (!node.IsMap()) return;
  if (const YAML::Node merged = node["<<"]) {
    expand_merge_keys(merged, source, visits);
    std::vector<YAML::Node> sources;
    if (merged.IsSequence()) {
      for (const auto& item : merged) sources.push_back(item);
    } else {
      sources.push_back(merged);
    }
    node.remove("<<");
    // yaml-cpp finds a key by comparing it with every key of the mapping:
    // looking each merged key up would take the product of the two sizes.
    std::set<std::string> given;
    for (const auto& entry : node) given.insert(entry.first.Scalar());
    for (const auto& from : sources) {
      if (!from.IsMap())
        throw InputError(location_in(source, from.Mark()), "<<",
                         "a merge key takes a mapping or a list of mappings (`<<: *defaults`), "
                         "not a value; nothing of it would be merged");
      for (const auto& entry : from)
        if (given.insert(entry.first.Scalar()).second) node.force_insert(entry.first, entry.second);
    }
  }
  for (auto entry : node) expand_merge_keys(entry.second, source, visits);
}

// yaml-cpp reports a tab in the indentation as whatever it could not parse
// next; name the tab, the usual cause, when one precedes the error.
std::string tab_hint(const std::string& text, int error_line) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; number <= error_line && std::getline(lines, line); ++number) {
    const auto indent_end = line.find_first_not_of(" \t");
    if (line.substr(0, indent_end).find('\t') != std::string::npos) {
      return fmt::format(" (line {} is indented with a tab; YAML indents with spaces)", number);
    }
  }
  return {};
}

YAML::Node parse(const std::string& text, const SourceFile& source) {
  std::vector<YAML::Node> documents;
  try {
    // Before any node is built: the walks below, and every program's, would
    // recurse without end through a cycle and take years over an alias bomb.
    check_expansion(text, source, {Document::max_expanded_nodes, Document::max_depth});
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& error) {
    const SourceLocation where = location_in(source, error.mark);
    throw InputError(where, "", "YAML syntax error: " + error.msg + tab_hint(text, where.line));
  }
  if (documents.empty() || documents.front().IsNull()) {
    throw InputError(SourceLocation{source.name.string(), 0, 0}, "", "the file is empty");
  }
  if (documents.size() > 1) {
    throw InputError(location_in(source, documents[1].Mark()), "",
                     "a second YAML document ('---') follows the first; a cosim file holds one");
  }
  Visits checked, expanded;
  refuse_duplicate_keys(documents.front(), source, "", checked);
  expand_merge_keys(documents.front(), source, expanded);
  return documents.front();
}

}  // namespace

Document::Document(std::string text, std::shared_ptr<const SourceFile> source, YAML::Node root)
    : text_(std::move(text)), source_(std::move(source)), root_(std::move(root)) {}

Document Document::load_string(std::string_view text, const std::filesystem::path& name) {
  const std::filesystem::path directory =
      name.empty() ? std::filesystem::current_path()
                   : std::filesystem::absolute(name).parent_path().lexically_normal();
  auto source = std::make_shared<const SourceFile>(SourceFile{name, directory});
  std::string owned(text);
  YAML::Node root = parse(owned, *source);
  return Document(std::move(owned), std::move(source), std::move(root));
}

Document Document::load_file(const std::filesystem::path& file) {
  const SourceLocation whole_file{file.string(), 0, 0};
  std::error_code status;
  if (!std::filesystem::exists(file, status)) throw InputError(whole_file, "", "file not found");
  if (std::filesystem::is_directory(file, status)) {
    throw InputError(whole_file, "", "is a directory, not a YAML file");
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(whole_file, "", "cannot read the file");
  return load_string(text.str(), file);
}

Node Document::root() const {
  return Node(root_, source_, "", YAML::Mark::null_mark());
}

}  // namespace cosim::config

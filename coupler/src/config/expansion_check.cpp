#include "expansion_check.hpp"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

namespace cosim::config {

namespace {

// A node with its aliases expanded.
struct Extent {
  std::uint64_t nodes = 1;
  int depth = 1;  // levels, its own included
};

struct Anchor {
  std::string name;
  YAML::Mark mark;
  Extent extent;
  bool ended = false;  // an alias to it before its end lies inside it
};

// A sequence or mapping whose end has not been read yet.
struct OpenNode {
  YAML::anchor_t anchor = YAML::NullAnchor;
  bool is_map = false;
  Extent extent;
  std::uint64_t children = 0;  // started so far; in a mapping, keys and values alternate
  std::string key;             // mappings: the key of the entry being read
};

// Sums each anchored node's expanded size and depth once, at its end, so that
// an alias costs one addition however large its expansion: the check takes
// the time of parsing, never that of expanding.
class ExpansionCheck final : public YAML::EventHandler {
 public:
  ExpansionCheck(const SourceFile& source, ExpansionLimits limits)
      : source_(source), limits_(limits) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    document_start_ = mark;
    anchors_.clear();
    open_.clear();
    total_ = 0;
  }
  void OnDocumentEnd() override {}

  const YAML::Mark& document_start() const { return document_start_; }

  // Comes just before the event of the node the anchor names.
  void OnAnchor(const YAML::Mark&, const std::string& name) override { next_anchor_name_ = name; }

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, "~"); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string& value) override {
    leaf(mark, anchor, value);
  }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t id) override {
    const auto found = anchors_.find(id);
    if (found == anchors_.end()) return;  // the parser refuses an unknown anchor itself
    const Anchor& anchor = found->second;
    start_child(anchor.name.empty() ? "*" : "*" + anchor.name);
    if (!anchor.ended) {
      fail(mark, fmt::format("alias '*{0}' lies inside the node anchored as '&{0}' at line {1}: "
                             "that node would contain itself without end",
                             anchor.name, location_in(source_, anchor.mark).line));
    }
    add(mark, anchor.extent, &anchor);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapEnd() override { close(); }

 private:
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string& value) {
    start_child(value);
    begin_anchor(anchor, mark);
    add(mark, Extent{}, nullptr);
    end_anchor(anchor, Extent{});
  }

  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool is_map) {
    start_child("?");
    begin_anchor(anchor, mark);
    ++total_;
    check(mark, static_cast<int>(open_.size()) + 1, nullptr);
    open_.push_back(OpenNode{anchor, is_map, Extent{}, 0, {}});
  }

  void close() {
    const OpenNode node = open_.back();
    open_.pop_back();
    end_anchor(node.anchor, node.extent);
    include_in_parent(node.extent);
  }

  // An anchor is known from its node's start, so that an alias inside the
  // node finds it unfinished.
  void begin_anchor(YAML::anchor_t id, const YAML::Mark& mark) {
    if (id == YAML::NullAnchor) return;
    anchors_[id] = Anchor{next_anchor_name_, mark, {}, false};
    next_anchor_name_.clear();
  }

  void end_anchor(YAML::anchor_t id, const Extent& extent) {
    if (id == YAML::NullAnchor) return;
    Anchor& anchor = anchors_[id];
    anchor.extent = extent;
    anchor.ended = true;
  }

  // Counts a node, or an alias's expansion, at the place being read.
  void add(const YAML::Mark& mark, const Extent& extent, const Anchor* via) {
    total_ += extent.nodes;
    check(mark, static_cast<int>(open_.size()) + extent.depth, via);
    include_in_parent(extent);
  }

  void include_in_parent(const Extent& extent) {
    if (open_.empty()) return;
    Extent& parent = open_.back().extent;
    parent.nodes += extent.nodes;
    parent.depth = std::max(parent.depth, extent.depth + 1);
  }

  // Counts are bounded: every addition is checked, and each term is at most
  // the limit (an anchored node was checked while it was read).
  void check(const YAML::Mark& mark, int depth, const Anchor* via) const {
    if (depth > limits_.depth) {
      fail(mark, via ? fmt::format("with alias '*{}' expanded the document nests {} levels deep "
                                   "here (the alias adds {}); the limit is {} levels",
                                   via->name, depth, via->extent.depth, limits_.depth)
                     : fmt::format("the document nests more than {} levels deep here (the limit)",
                                   limits_.depth));
    }
    if (total_ > limits_.nodes) {
      fail(mark,
           via ? fmt::format("with its aliases expanded the document holds more than {} "
                             "nodes (the limit): alias '*{}' here adds {}, bringing it to {}",
                             limits_.nodes, via->name, via->extent.nodes, total_)
               : fmt::format("the document holds more than {} nodes (the limit)", limits_.nodes));
    }
  }

  // Records where the node that starts now sits in its parent, for the key
  // path of a message.
  void start_child(const std::string& text) {
    if (open_.empty()) return;
    OpenNode& parent = open_.back();
    if (parent.is_map && parent.children % 2 == 0) parent.key = text;
    ++parent.children;
  }

  std::string key_path() const {
    std::string path;
    for (const OpenNode& node : open_) {
      const std::uint64_t child = node.children - 1;
      if (!node.is_map) {
        path += fmt::format("[{}]", child);
      } else if (child % 2 == 1) {
        path += (path.empty() ? "" : ".") + node.key;
      }
    }
    return path;
  }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const {
    throw InputError(location_in(source_, mark), key_path(), what);
  }

  const SourceFile& source_;
  ExpansionLimits limits_;
  std::map<YAML::anchor_t, Anchor> anchors_;
  std::string next_anchor_name_;
  std::vector<OpenNode> open_;
  std::uint64_t total_ = 0;
  YAML::Mark document_start_;
};

}  // namespace

void check_expansion(const std::string& text, const SourceFile& source, ExpansionLimits limits) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  ExpansionCheck check(source, limits);
  int previous_start = -1;
  while (parser.HandleNextDocument(check)) {
    // yaml-cpp 0.7 leaves a stray flow token (a lone ',') where it is and
    // reads the same empty document there again, without end.
    const YAML::Mark& start = check.document_start();
    if (start.pos == previous_start) {
      const auto at = static_cast<std::size_t>(start.pos);
      throw YAML::ParserException(
          start, at < text.size() ? fmt::format("unexpected '{}'", text[at]) : "unexpected end");
    }
    previous_start = start.pos;
  }
}

}  // namespace cosim::config

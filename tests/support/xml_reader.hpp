#pragma once

#include <cctype>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

// A minimal XML reader for checking the XDMF index in tests: elements,
// attributes (quoted), text, the XML declaration and the five predefined
// entities. Throws std::runtime_error on anything not well-formed.
namespace cosim::testing {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<std::unique_ptr<XmlElement>> children;

  std::vector<const XmlElement*> all(std::string_view child_name) const {
    std::vector<const XmlElement*> found;
    for (const auto& c : children)
      if (c->name == child_name) found.push_back(c.get());
    return found;
  }
  const XmlElement& one(std::string_view child_name) const {
    const auto found = all(child_name);
    if (found.size() != 1)
      throw std::runtime_error("expected one <" + std::string(child_name) + "> in <" + name +
                               ">, found " + std::to_string(found.size()));
    return *found.front();
  }
  const std::string& attribute(const std::string& key) const {
    const auto it = attributes.find(key);
    if (it == attributes.end()) throw std::runtime_error("<" + name + "> has no attribute " + key);
    return it->second;
  }
};

class XmlReader {
 public:
  static std::unique_ptr<XmlElement> parse(std::string_view text) {
    XmlReader reader(text);
    reader.skip_space();
    if (reader.starts_with("<?xml")) {
      const std::size_t end = text.find("?>", reader.pos_);
      if (end == std::string_view::npos) reader.fail("unterminated XML declaration");
      reader.pos_ = end + 2;
    }
    reader.skip_space();
    auto root = reader.element();
    reader.skip_space();
    if (reader.pos_ != text.size()) reader.fail("content after the root element");
    return root;
  }

 private:
  explicit XmlReader(std::string_view text) : text_(text) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML at offset " + std::to_string(pos_) + ": " + what);
  }
  bool starts_with(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  void expect(std::string_view s) {
    if (!starts_with(s)) fail("expected '" + std::string(s) + "'");
    pos_ += s.size();
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  std::string name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
            text_[pos_] == ':' || text_[pos_] == '-' || text_[pos_] == '.'))
      ++pos_;
    if (pos_ == start) fail("expected a name");
    return std::string(text_.substr(start, pos_ - start));
  }
  std::string decoded(std::string_view raw) const {
    std::string out;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '<') fail("'<' in text or attribute");
      if (raw[i] != '&') {
        out += raw[i];
        continue;
      }
      static const std::map<std::string_view, char> entities{
          {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
      bool matched = false;
      for (const auto& [entity, c] : entities)
        if (raw.substr(i, entity.size()) == entity) {
          out += c;
          i += entity.size() - 1;
          matched = true;
          break;
        }
      if (!matched) fail("unknown entity");
    }
    return out;
  }
  std::unique_ptr<XmlElement> element() {
    expect("<");
    auto e = std::make_unique<XmlElement>();
    e->name = name();
    for (;;) {
      skip_space();
      if (starts_with("/>")) {
        pos_ += 2;
        return e;
      }
      if (starts_with(">")) {
        ++pos_;
        break;
      }
      const std::string key = name();
      skip_space();
      expect("=");
      skip_space();
      if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\'')) fail("unquoted");
      const char quote = text_[pos_++];
      const std::size_t end = text_.find(quote, pos_);
      if (end == std::string_view::npos) fail("unterminated attribute");
      if (!e->attributes.emplace(key, decoded(text_.substr(pos_, end - pos_))).second)
        fail("duplicate attribute " + key);
      pos_ = end + 1;
    }
    for (;;) {
      const std::size_t next = text_.find('<', pos_);
      if (next == std::string_view::npos) fail("unterminated <" + e->name + ">");
      e->text += decoded(text_.substr(pos_, next - pos_));
      pos_ = next;
      if (starts_with("</")) {
        pos_ += 2;
        if (name() != e->name) fail("mismatched closing tag for <" + e->name + ">");
        skip_space();
        expect(">");
        return e;
      }
      e->children.push_back(element());
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace cosim::testing

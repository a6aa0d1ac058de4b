#include "openfoam/case/mesh_cell_count.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace openfoam {

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file, std::size_t most_bytes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  std::string text(most_bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(most_bytes));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// The owner file's header note: "nPoints:... nCells:N nFaces:...".
std::optional<double> owner_note_cells(const fs::path& owner) {
  const std::string header = read_text(owner, 4096);
  const auto at = header.find("nCells:");
  if (at == std::string::npos) return std::nullopt;
  std::size_t end = at + 7;
  while (end < header.size() && std::isdigit(static_cast<unsigned char>(header[end]))) ++end;
  if (end == at + 7) return std::nullopt;
  return std::strtod(header.substr(at + 7, end - at - 7).c_str(), nullptr);
}

// The dictionary's words and brackets, comments dropped.
std::vector<std::string> tokens(const std::string& text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    } else if (text.compare(i, 2, "/*") == 0) {
      i = text.find("*/", i + 2);
      if (i == std::string::npos) break;
      i += 2;
    } else if (c == '(' || c == ')' || c == ';') {
      out.emplace_back(1, c);
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
             text[i] != '(' && text[i] != ')' && text[i] != ';')
        ++i;
      out.push_back(text.substr(start, i - start));
    }
  }
  return out;
}

bool whole_number(const std::string& word) {
  if (word.empty()) return false;
  for (char c : word)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Sum of nx ny nz over `blocks ( hex (v...) (nx ny nz) grading (...) ... )`.
std::optional<double> block_mesh_cells(const fs::path& dict) {
  const std::vector<std::string> t = tokens(read_text(dict, 1 << 20));
  std::size_t i = 0;
  while (i + 1 < t.size() && !(t[i] == "blocks" && t[i + 1] == "(")) ++i;
  if (i + 1 >= t.size()) return std::nullopt;
  i += 2;
  double cells = 0.0;
  int blocks = 0;
  while (i < t.size() && t[i] != ")") {
    if (t[i] != "hex") {
      // A grading's list or a zone name: skip a bracketed group whole.
      if (t[i] == "(") {
        int depth = 0;
        do {
          depth += t[i] == "(" ? 1 : t[i] == ")" ? -1 : 0;
          ++i;
        } while (i < t.size() && depth > 0);
      } else {
        ++i;
      }
      continue;
    }
    // hex ( 8 vertices ) [zone] ( nx ny nz )
    if (i + 10 >= t.size() || t[i + 1] != "(" || t[i + 10] != ")") return std::nullopt;
    std::size_t counts = i + 11;
    if (counts < t.size() && t[counts] != "(") ++counts;
    if (counts + 4 >= t.size() || t[counts] != "(" || t[counts + 4] != ")") return std::nullopt;
    double block = 1.0;
    for (std::size_t k = counts + 1; k < counts + 4; ++k) {
      if (!whole_number(t[k])) return std::nullopt;
      block *= std::strtod(t[k].c_str(), nullptr);  // inf beyond a double, refused by the size
    }
    cells += block;
    ++blocks;
    i = counts + 5;
  }
  if (blocks == 0) return std::nullopt;
  return cells;
}

}  // namespace

std::optional<double> mesh_cell_count(const fs::path& case_dir) {
  const fs::path owner = case_dir / "constant" / "polyMesh" / "owner";
  if (fs::is_regular_file(owner)) return owner_note_cells(owner);
  const fs::path dict = case_dir / "system" / "blockMeshDict";
  if (fs::is_regular_file(dict)) return block_mesh_cells(dict);
  return std::nullopt;
}

}  // namespace openfoam

#include "text_files.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cosim::testing {

namespace {

// strtod, not stod: a subnormal value (a velocity of 1e-315 m/s in a gauge)
// is a number, which stod refuses as out of range.
double parse_number(const std::string& cell, const std::filesystem::path& file, std::size_t line) {
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (end == cell.c_str() || *end != '\0')
    throw std::invalid_argument(file.string() + ":" + std::to_string(line) + ": '" + cell +
                                "' is not a number");
  return value;
}

}  // namespace

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::vector<std::vector<double>> read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  std::size_t number = 1;
  while (std::getline(in, line)) {
    ++number;
    std::vector<double> row;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(parse_number(cell, file, number));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace cosim::testing

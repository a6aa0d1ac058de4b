#pragma once

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mpm/case/load_case.hpp"

namespace mpm::validation {

// A case file loaded with its grid cells multiplied by `scale` (the bodies
// are seeded per cell, so the particles follow): the MPM validation tests
// run coarser in CI than the case files users run.
inline CaseDescription load_case_scaled(const std::string& path, double scale) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::regex cells(R"(cells: \[(\d+), (\d+)\])");
  std::smatch m;
  if (!std::regex_search(yaml, m, cells))
    throw std::runtime_error("no `cells: [nx, ny]` in " + path);
  const auto scaled = [&](const std::string& n) { return std::lround(std::stod(n) * scale); };
  const std::string replacement =
      fmt::format("cells: [{}, {}]", scaled(m[1].str()), scaled(m[2].str()));
  yaml = std::regex_replace(yaml, cells, replacement, std::regex_constants::format_first_only);
  return load_case_text(yaml, path);
}

}  // namespace mpm::validation

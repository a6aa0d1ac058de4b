#include "mpm/geometry/particle_file.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "cosim/error.hpp"

namespace mpm {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// A comma-separated field and the 1-based column where it starts.
struct Field {
  std::string_view text;
  int column = 1;
};

std::vector<Field> split(std::string_view line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::string_view raw = line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    const std::size_t lead = raw.find_first_not_of(" \t");
    fields.push_back({trim(raw), static_cast<int>(start + (lead == raw.npos ? 0 : lead)) + 1});
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

bool skipped(std::string_view line) {
  const std::string_view t = trim(line);
  return t.empty() || t.front() == '#';
}

}  // namespace

template <int Dim>
ParticleFile<Dim> read_particle_file(const std::string& path) {
  auto fail = [&path](int line, int column, const std::string& what) -> cosim::InputError {
    return cosim::InputError(cosim::SourceLocation{path, line, column}, "", what);
  };
  std::ifstream in(path);
  if (!in) throw fail(0, 0, "cannot open the particle file");

  std::string line;
  int line_number = 0;
  bool have_header = false;
  while (!have_header && std::getline(in, line)) {
    ++line_number;
    have_header = !skipped(line);
  }
  if (!have_header) throw fail(0, 0, "particle file has no header row (expected x,y" +
                                         std::string(Dim == 3 ? ",z" : "") + ",volume)");

  // Header: the column of every required name, the rest are extra.
  const std::vector<Field> header = split(line);
  const int header_line = line_number;
  const char* required[] = {"x", "y", Dim == 3 ? "z" : "volume", "volume"};
  constexpr int required_count = Dim + 1;
  std::array<int, required_count> column_of;
  column_of.fill(-1);
  std::vector<std::string> names;
  std::vector<int> extra_index;  // header position of each extra column
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string name(header[i].text);
    if (name.empty()) throw fail(header_line, header[i].column, "empty column name in the header");
    for (const std::string& seen : names)
      if (seen == name) throw fail(header_line, header[i].column, "column '" + name + "' appears twice");
    names.push_back(name);
    bool is_required = false;
    for (int r = 0; r < required_count; ++r) {
      if (name == required[r]) {
        column_of[static_cast<std::size_t>(r)] = static_cast<int>(i);
        is_required = true;
      }
    }
    if (!is_required) extra_index.push_back(static_cast<int>(i));
  }
  for (int r = 0; r < required_count; ++r) {
    if (column_of[static_cast<std::size_t>(r)] < 0)
      throw fail(header_line, 1, std::string("header has no column '") + required[r] +
                                     "' (required: x,y" + (Dim == 3 ? ",z" : "") + ",volume)");
  }

  ParticleFile<Dim> result;
  std::vector<std::vector<double>*> extra;
  for (int i : extra_index) extra.push_back(&result.extra_columns[names[static_cast<std::size_t>(i)]]);
  std::vector<double> values(header.size());
  while (std::getline(in, line)) {
    ++line_number;
    if (skipped(line)) continue;
    const std::vector<Field> fields = split(line);
    if (fields.size() != header.size())
      throw fail(line_number, 1, "expected " + std::to_string(header.size()) + " values (as the header), got " +
                                     std::to_string(fields.size()));
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const std::string_view text = fields[i].text;
      double value = 0.0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw fail(line_number, fields[i].column,
                   "column '" + names[i] + "': '" + std::string(text) + "' is not a finite number");
      values[i] = value;
    }
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = values[static_cast<std::size_t>(column_of[static_cast<std::size_t>(d)])];
    const auto volume_column = static_cast<std::size_t>(column_of[Dim]);
    const double volume = values[volume_column];
    if (!(volume > 0.0))
      throw fail(line_number, fields[volume_column].column,
                 "volume must be positive, got " + std::string(fields[volume_column].text));
    result.particles.positions.push_back(x);
    result.particles.volumes.push_back(volume);
    result.particles.half_lengths.push_back(Vec<Dim>::Constant(0.5 * std::pow(volume, 1.0 / Dim)));
    for (std::size_t e = 0; e < extra.size(); ++e)
      extra[e]->push_back(values[static_cast<std::size_t>(extra_index[e])]);
  }
  if (result.particles.positions.empty()) throw fail(line_number, 0, "particle file lists no particles");
  return result;
}

template ParticleFile<2> read_particle_file<2>(const std::string&);
template ParticleFile<3> read_particle_file<3>(const std::string&);

}  // namespace mpm

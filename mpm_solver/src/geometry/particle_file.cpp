#include "mpm/geometry/particle_file.hpp"

#include <array>
#include <cmath>

#include "cosim/error.hpp"
#include "cosim/io/csv_table.hpp"

namespace mpm {

template <int Dim>
ParticleFile<Dim> read_particle_file(const std::string& path) {
  const cosim::CsvTable table = cosim::CsvTable::read(path);

  // Header: the column of every required name, the rest are extra.
  const auto& header = table.header_cells();
  const int header_line = table.header_line();
  const char* required[] = {"x", "y", Dim == 3 ? "z" : "volume", "volume"};
  constexpr int required_count = Dim + 1;
  std::array<int, required_count> column_of;
  column_of.fill(-1);
  std::vector<int> extra_index;  // header position of each extra column
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& name = header[i].text;
    if (name.empty()) table.fail(header_line, header[i].column, "empty column name in the header");
    for (std::size_t j = 0; j < i; ++j)
      if (header[j].text == name)
        table.fail(header_line, header[i].column, "column '" + name + "' appears twice");
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
      table.fail(header_line, 1,
                 std::string("header has no column '") + required[r] + "' (required: x,y" +
                     (Dim == 3 ? ",z" : "") + ",volume)");
  }

  ParticleFile<Dim> result;
  std::vector<std::vector<double>*> extra;
  for (int i : extra_index)
    extra.push_back(&result.extra_columns[header[static_cast<std::size_t>(i)].text]);
  std::vector<double> values(header.size());
  for (std::size_t row = 0; row < table.rows(); ++row) {
    const auto& cells = table.cells(row);
    if (cells.size() != header.size())
      table.fail(table.line(row), 1,
                 "expected " + std::to_string(header.size()) + " values (as the header), got " +
                     std::to_string(cells.size()));
    for (std::size_t i = 0; i < cells.size(); ++i) values[i] = table.number(row, i);
    Vec<Dim> x;
    for (int d = 0; d < Dim; ++d)
      x[d] = values[static_cast<std::size_t>(column_of[static_cast<std::size_t>(d)])];
    const auto volume_column = static_cast<std::size_t>(column_of[Dim]);
    const double volume = values[volume_column];
    if (!(volume > 0.0))
      table.fail(table.line(row), cells[volume_column].column,
                 "volume must be positive, got " + cells[volume_column].text);
    result.particles.positions.push_back(x);
    result.particles.volumes.push_back(volume);
    result.particles.half_lengths.push_back(Vec<Dim>::Constant(0.5 * std::pow(volume, 1.0 / Dim)));
    for (std::size_t e = 0; e < extra.size(); ++e)
      extra[e]->push_back(values[static_cast<std::size_t>(extra_index[e])]);
  }
  if (result.particles.positions.empty())
    table.fail(table.last_line(), 0, "particle file lists no particles");
  return result;
}

template ParticleFile<2> read_particle_file<2>(const std::string&);
template ParticleFile<3> read_particle_file<3>(const std::string&);

}  // namespace mpm

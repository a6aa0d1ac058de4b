#include "ice/io/state_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"

namespace ice {

namespace {

constexpr const char* axis_name[] = {"x", "y", "z"};

template <int Dim>
std::vector<std::string> gauge_columns(const std::vector<GaugePoint>& gauges,
                                       const std::vector<WaveGauge>& wave_gauges,
                                       const IceSolver<Dim>& solver) {
  std::vector<std::string> columns{cosim::column_name("time", "s")};
  for (const GaugePoint& g : gauges) {
    columns.push_back(cosim::column_name("p_" + g.name, "Pa"));
    for (int d = 0; d < Dim; ++d) {
      columns.push_back(cosim::column_name(fmt::format("u{}_{}", axis_name[d], g.name), "m/s"));
    }
    for (const FluidMaterial& m : solver.materials()) {
      columns.push_back(cosim::column_name(fmt::format("{}_fraction_{}", m.name, g.name), "1"));
    }
  }
  for (const WaveGauge& g : wave_gauges)
    columns.push_back(cosim::column_name("eta_" + g.name, "m"));
  return columns;
}

template <int Dim>
int cell_holding(const CellGrid<Dim>& grid, const GaugePoint& gauge) {
  typename CellGrid<Dim>::CellIndex ijk{};
  for (int d = 0; d < Dim; ++d) {
    const double offset =
        (gauge.point[static_cast<std::size_t>(d)] - grid.origin()[d]) / grid.spacing()[d];
    const int cells = grid.cells()[static_cast<std::size_t>(d)];
    if (!(offset >= 0.0 && offset <= cells)) {
      throw cosim::InputError(
          fmt::format("gauge '{}' lies outside the grid along {}", gauge.name, axis_name[d]));
    }
    ijk[static_cast<std::size_t>(d)] = std::min(cells - 1, static_cast<int>(std::floor(offset)));
  }
  return grid.cell(ijk);
}

}  // namespace

template <int Dim>
cosim::Mesh cell_mesh(const CellGrid<Dim>& grid, const std::string& name) {
  cosim::UniformGrid mesh;
  mesh.dim = Dim;
  for (int d = 0; d < Dim; ++d) {
    mesh.origin[static_cast<std::size_t>(d)] = grid.origin()[d];
    mesh.spacing[static_cast<std::size_t>(d)] = grid.spacing()[d];
    mesh.cells[static_cast<std::size_t>(d)] = grid.cells()[static_cast<std::size_t>(d)];
  }
  mesh.location = cosim::GridLocation::cell;
  return {name, mesh};
}

template <int Dim>
const cosim::SnapshotFields& SnapshotFieldSet<Dim>::fields(const IceSolver<Dim>& solver) {
  const FluidState<Dim>& state = solver.state();
  const std::size_t cells = state.pressure.size();
  const std::size_t n = state.materials.size();
  const auto dim = static_cast<std::size_t>(Dim);
  mixture_density_.assign(cells, 0.0);
  mixture_velocity_.assign(cells * dim, 0.0);
  velocity_.resize(n);
  for (std::size_t m = 0; m < n; ++m) {
    const MaterialState<Dim>& material = state.materials[m];
    velocity_[m].resize(cells * dim);
    for (std::size_t c = 0; c < cells; ++c) {
      mixture_density_[c] += material.bulk_density[c];
      for (std::size_t d = 0; d < dim; ++d) {
        velocity_[m][c * dim + d] = material.velocity[d][c];
        mixture_velocity_[c * dim + d] += material.bulk_density[c] * material.velocity[d][c];
      }
    }
  }
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t d = 0; d < dim; ++d) mixture_velocity_[c * dim + d] /= mixture_density_[c];
  }
  fields_.clear();
  const auto key = [](const std::string& name) { return name; };
  fields_.emplace("pressure", cosim::FieldView{state.pressure, 1, "Pa"});
  fields_.emplace("density", cosim::FieldView{mixture_density_, 1, "kg/m^3"});
  fields_.emplace("velocity", cosim::FieldView{mixture_velocity_, Dim, "m/s"});
  for (std::size_t m = 0; m < n; ++m) {
    const MaterialState<Dim>& material = state.materials[m];
    const std::string& name = solver.materials()[m].name;
    fields_.emplace(key("volume_fraction_" + name),
                    cosim::FieldView{material.volume_fraction, 1, "1"});
    fields_.emplace(key("bulk_density_" + name),
                    cosim::FieldView{material.bulk_density, 1, "kg/m^3"});
    fields_.emplace(key("density_" + name), cosim::FieldView{material.density, 1, "kg/m^3"});
    fields_.emplace(key("velocity_" + name), cosim::FieldView{velocity_[m], Dim, "m/s"});
    fields_.emplace(key("temperature_" + name), cosim::FieldView{material.temperature, 1, "K"});
  }
  return fields_;
}

template <int Dim>
GaugeRecorder<Dim>::GaugeRecorder(const std::filesystem::path& file,
                                  const std::vector<GaugePoint>& gauges,
                                  const IceSolver<Dim>& solver,
                                  const std::vector<WaveGauge>& wave_gauges) {
  locate(gauges, solver, wave_gauges, solver.grid(), [](int cell) { return cell; });
  writer_.emplace(file, gauge_columns(gauges, wave_gauges, solver));
  row_.resize(writer_->columns().size());
}

template <int Dim>
GaugeRecorder<Dim>::GaugeRecorder(const std::filesystem::path& file,
                                  const std::vector<GaugePoint>& gauges,
                                  const IceSolver<Dim>& solver,
                                  const std::vector<WaveGauge>& wave_gauges,
                                  const Decomposed& decomposed, bool writes) {
  locate(gauges, solver, wave_gauges, decomposed.whole, decomposed.local);
  const auto columns = gauge_columns(gauges, wave_gauges, solver);
  row_.resize(columns.size());
  if (writes) writer_.emplace(file, columns);
}

template <int Dim>
void GaugeRecorder<Dim>::locate(const std::vector<GaugePoint>& gauges, const IceSolver<Dim>& solver,
                                const std::vector<WaveGauge>& wave_gauges,
                                const CellGrid<Dim>& grid, const std::function<int(int)>& local) {
  for (const GaugePoint& g : gauges) cells_.push_back(local(cell_holding(grid, g)));
  for (const WaveGauge& g : wave_gauges) {
    const auto& materials = solver.materials();
    const auto material =
        std::find_if(materials.begin(), materials.end(),
                     [&](const FluidMaterial& m) { return m.name == g.material; });
    if (material == materials.end())
      throw cosim::InputError(fmt::format("wave gauge '{}': no material '{}'", g.name, g.material));
    if (g.vertical < 0 || g.vertical >= Dim)
      throw cosim::InputError(fmt::format("wave gauge '{}': a {}D case has no vertical axis {}",
                                          g.name, Dim,
                                          g.vertical < 3 ? axis_name[g.vertical] : "?"));
    // The column's bottom cell: the point moved down to the grid's floor.
    GaugePoint bottom{g.name, g.point};
    bottom.point[static_cast<std::size_t>(g.vertical)] = grid.origin()[g.vertical];
    const int first = cell_holding(grid, bottom);
    Column column{{},
                  static_cast<std::size_t>(material - materials.begin()),
                  grid.origin()[g.vertical],
                  grid.spacing()[g.vertical]};
    for (int j = 0; j < grid.cells()[static_cast<std::size_t>(g.vertical)]; ++j)
      column.cells.push_back(local(first + j * grid.stride(g.vertical)));
    columns_.push_back(std::move(column));
  }
}

template <int Dim>
void GaugeRecorder<Dim>::record(double time, const IceSolver<Dim>& solver) {
  writer_->append(row(time, solver));
}

template <int Dim>
std::span<const double> GaugeRecorder<Dim>::row(double time, const IceSolver<Dim>& solver,
                                                const Sum& sum) {
  const FluidState<Dim>& state = solver.state();
  const std::size_t per_gauge = 1 + static_cast<std::size_t>(Dim) + state.materials.size();
  values_.clear();
  for (const int cell : cells_) {
    if (cell < 0) {
      values_.insert(values_.end(), per_gauge, -0.0);
      continue;
    }
    const auto c = static_cast<std::size_t>(cell);
    values_.push_back(state.pressure[c]);
    double mass = 0.0;
    for (const MaterialState<Dim>& m : state.materials) mass += m.bulk_density[c];
    for (std::size_t d = 0; d < static_cast<std::size_t>(Dim); ++d) {
      double momentum = 0.0;
      for (const MaterialState<Dim>& m : state.materials)
        momentum += m.bulk_density[c] * m.velocity[d][c];
      values_.push_back(momentum / mass);
    }
    for (const MaterialState<Dim>& m : state.materials) values_.push_back(m.volume_fraction[c]);
  }
  for (const Column& column : columns_) {
    const CellField& fraction = state.materials[column.material].volume_fraction;
    for (const int cell : column.cells) {
      if (cell < 0) {
        values_.push_back(-0.0);
        continue;
      }
      const auto c = static_cast<std::size_t>(cell);
      // A cell the solid fills counts as the saturated soil's cells do: whole.
      const double pores = state.porosity.empty() ? 1.0 : state.porosity[c];
      values_.push_back((pores > 1e-9 ? fraction[c] / pores : 1.0) * column.cell_height);
    }
  }
  if (sum) sum(values_);
  std::size_t k = 0, v = 0;
  row_[k++] = time;
  for (; v < per_gauge * cells_.size(); ++v) row_[k++] = values_[v];
  for (const Column& column : columns_) {
    double height = column.bottom;
    for (std::size_t j = 0; j < column.cells.size(); ++j) height += values_[v++];
    row_[k++] = height;
  }
  return row_;
}

template cosim::Mesh cell_mesh<1>(const CellGrid<1>&, const std::string&);
template cosim::Mesh cell_mesh<2>(const CellGrid<2>&, const std::string&);
template cosim::Mesh cell_mesh<3>(const CellGrid<3>&, const std::string&);
template class SnapshotFieldSet<1>;
template class SnapshotFieldSet<2>;
template class SnapshotFieldSet<3>;
template class GaugeRecorder<1>;
template class GaugeRecorder<2>;
template class GaugeRecorder<3>;

}  // namespace ice

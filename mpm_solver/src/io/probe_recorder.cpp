#include "mpm/io/probe_recorder.hpp"

#include <span>
#include <string>

namespace mpm {

namespace {

constexpr const char* axes[] = {"x", "y", "z"};
// Voigt indices (xx yy zz xy yz xz) recorded per dimension.
constexpr std::size_t stress_components_2d[] = {0, 1, 2, 3};
constexpr const char* voigt_names[] = {"xx", "yy", "zz", "xy", "yz", "xz"};

template <int Dim>
std::vector<std::size_t> stress_components() {
  if constexpr (Dim == 2) {
    return {std::begin(stress_components_2d), std::end(stress_components_2d)};
  } else {
    return {0, 1, 2, 3, 4, 5};
  }
}

// The seeded position of the point with id `id`.
template <int Dim>
Vec<Dim> seeded_position(const CaseDescription& description, std::size_t id) {
  for (const BodySpec& body : description.bodies) {
    if (id < body.positions.size()) return body.positions[id].head<Dim>();
    id -= body.positions.size();
  }
  return Vec<Dim>::Zero();
}

}  // namespace

template <int Dim>
std::vector<std::string> ProbeRecorder<Dim>::columns(const std::vector<ProbeSpec>& probes,
                                                     bool thermal) {
  std::vector<std::string> names{cosim::column_name("time", "s")};
  for (const auto& probe : probes) {
    for (int d = 0; d < Dim; ++d)
      names.push_back(cosim::column_name(probe.name + "_displacement_" + axes[d], "m"));
    for (int d = 0; d < Dim; ++d)
      names.push_back(cosim::column_name(probe.name + "_velocity_" + axes[d], "m/s"));
    for (const std::size_t c : stress_components<Dim>())
      names.push_back(cosim::column_name(probe.name + "_stress_" + voigt_names[c], "Pa"));
    names.push_back(cosim::column_name(probe.name + "_pore_pressure", "Pa"));
    names.push_back(cosim::column_name(probe.name + "_plastic_strain", "-"));
    if (thermal) names.push_back(cosim::column_name(probe.name + "_temperature", "K"));
  }
  return names;
}

template <int Dim>
ProbeRecorder<Dim>::ProbeRecorder(const std::filesystem::path& file, const Solver<Dim>& solver,
                                  SumOverRanks sum_over_ranks, bool writes)
    : probes_(solver.description().probes),
      thermal_(solver.conducts_heat()),
      sum_over_ranks_(std::move(sum_over_ranks)),
      columns_(columns(probes_, thermal_).size()) {
  if (writes) writer_.emplace(file, columns(probes_, thermal_));
  for (const auto& probe : probes_)
    initial_position_.push_back(seeded_position<Dim>(solver.description(), probe.particle));
}

template <int Dim>
void ProbeRecorder<Dim>::record(const Solver<Dim>& solver) {
  hold(solver);
  write_held();
}

template <int Dim>
void ProbeRecorder<Dim>::write_held() {
  if (writer_)
    for (std::size_t begin = 0; begin < held_.size(); begin += columns_)
      writer_->append(std::span<const double>(held_).subspan(begin, columns_));
  held_.clear();
}

template <int Dim>
void ProbeRecorder<Dim>::hold(const Solver<Dim>& solver) {
  const Particles<Dim>& p = solver.particles();
  const std::size_t row = held_.size();
  held_.push_back(solver.time());
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const std::size_t i = solver.local_index(probes_[k].particle);
    if (i == p.size()) {  // another rank's point
      held_.resize(held_.size() + (columns_ - 1) / probes_.size(), -0.0);
      continue;
    }
    const Vec<Dim> u = p.position[i] - initial_position_[k];
    for (int d = 0; d < Dim; ++d) held_.push_back(u[d]);
    for (int d = 0; d < Dim; ++d) held_.push_back(p.velocity[i][d]);
    const Voigt sigma = to_voigt(solver.total_stress(i));
    for (const std::size_t c : stress_components<Dim>()) held_.push_back(sigma[c]);
    held_.push_back(i < p.pore_pressure.size() ? p.pore_pressure[i] : 0.0);
    held_.push_back(i < p.plastic_strain.size() ? p.plastic_strain[i] : 0.0);
    if (thermal_) held_.push_back(p.temperature[i]);
  }
  if (sum_over_ranks_) {
    const double time = held_[row];
    held_[row] = -0.0;
    sum_over_ranks_(std::span<double>(held_).subspan(row));
    held_[row] = time;
  }
}

template class ProbeRecorder<2>;
template class ProbeRecorder<3>;

}  // namespace mpm

#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/coupling/coupling_channel.hpp"

// A partner for the coupling's unit tests: records what is declared and
// written, returns what the test sets, and hands out window integrals in
// shares like cosim::Participant::read_increment (the last step of a window
// gets the remainder, so the shares add up exactly).
namespace mpm::testing {

class MockChannel final : public coupling::CouplingChannel {
 public:
  struct Read {
    cosim::FieldSpec spec;
    std::vector<double> values;     // state: current values; integral: the window's integral
    std::vector<double> delivered;  // integral: handed out in this window
  };

  std::map<std::string, cosim::Mesh> meshes;
  std::map<std::string, cosim::FieldSpec> write_specs;
  std::map<std::string, std::vector<double>> written;
  std::map<std::string, int> write_count;
  std::map<std::string, Read> reads;
  double window = 1.0;
  double time = 0.0;

  std::map<std::string, cosim::MeshPart> parts;
  void declare_mesh(cosim::Mesh mesh) override { meshes[mesh.name] = std::move(mesh); }
  void declare_mesh(cosim::Mesh mesh, cosim::MeshPart part) override {
    parts[mesh.name] = std::move(part);
    meshes[mesh.name] = std::move(mesh);
  }
  void declare_write(cosim::FieldSpec field) override { write_specs[field.name] = field; }
  void declare_read(cosim::FieldSpec field, double default_value) override {
    const std::size_t n = size_of(field);
    Read r{
        field,
        std::vector<double>(n, field.time == cosim::TimeTreatment::integral ? 0.0 : default_value),
        std::vector<double>(n, 0.0)};
    reads[field.name] = std::move(r);
  }
  void write(std::string_view field, std::span<const double> values) override {
    const std::string name(field);
    if (!write_specs.count(name)) throw std::logic_error("write of undeclared " + name);
    if (values.size() != size_of(write_specs[name]))
      throw std::logic_error("wrong size for " + name);
    written[name].assign(values.begin(), values.end());
    ++write_count[name];
  }
  void read(std::string_view field, double, std::span<double> values) override {
    const Read& r = reads.at(std::string(field));
    if (values.size() != r.values.size()) throw std::logic_error("wrong read size");
    std::copy(r.values.begin(), r.values.end(), values.begin());
  }
  void read_increment(std::string_view field, double dt, std::span<double> values) override {
    Read& r = reads.at(std::string(field));
    const bool last = dt >= max_time_step() - 1e-9 * window;
    for (std::size_t i = 0; i < values.size(); ++i) {
      values[i] = last ? r.values[i] - r.delivered[i] : r.values[i] * std::min(1.0, dt / window);
      r.delivered[i] += values[i];
    }
  }
  double max_time_step() const override { return window_end() - time; }
  double window_size() const override { return window; }

  // The run loop's participant.advance(dt).
  void advance(double dt) {
    const bool completes = dt >= max_time_step() - 1e-9 * window;
    time = completes ? window_end() : time + dt;
    if (completes)
      for (auto& [name, r] : reads) std::fill(r.delivered.begin(), r.delivered.end(), 0.0);
  }
  // Sets a read field's values (a state field's current values or an
  // integral field's window integral).
  void set(const std::string& field, std::vector<double> values) {
    Read& r = reads.at(field);
    if (values.size() != r.values.size()) throw std::logic_error("wrong size set for " + field);
    r.values = std::move(values);
  }
  std::size_t size_of(const cosim::FieldSpec& f) const {
    return meshes.at(f.mesh).size() * static_cast<std::size_t>(f.components);
  }

 private:
  double window_end() const {
    const double k = std::floor(time / window + 1e-9);
    return (k + 1.0) * window;
  }
};

}  // namespace mpm::testing

#pragma once

#include <span>
#include <string_view>

#include "cosim/field.hpp"
#include "cosim/mesh.hpp"

namespace cosim {
class Participant;
}

namespace mpm::coupling {

// What the MPM coupling needs of the coupler: the part of cosim::Participant
// it calls, behind an interface so unit tests can drive the exchanges with a
// mock partner. Meaning and units as in cosim/participant.hpp.
class CouplingChannel {
 public:
  virtual ~CouplingChannel() = default;

  virtual void declare_mesh(cosim::Mesh mesh) = 0;
  // This rank's part of the mesh (a participant on several ranks).
  virtual void declare_mesh(cosim::Mesh mesh, cosim::MeshPart part) = 0;
  virtual void declare_write(cosim::FieldSpec field) = 0;
  virtual void declare_read(cosim::FieldSpec field, double default_value) = 0;

  virtual void write(std::string_view field, std::span<const double> values) = 0;
  // State fields, for a step of dt from now: the latest values received, or,
  // when they vary within the window (time_interpolation: linear), their
  // values at the step's middle.
  virtual void read(std::string_view field, double dt, std::span<double> values) = 0;
  // Integral fields: the share of the window's integral for a step of dt.
  virtual void read_increment(std::string_view field, double dt, std::span<double> values) = 0;

  // The longest step that stays inside the current window, and the window.
  virtual double max_time_step() const = 0;
  virtual double window_size() const = 0;
};

// The production channel: a cosim::Participant (coupled or standalone).
class ParticipantChannel final : public CouplingChannel {
 public:
  explicit ParticipantChannel(cosim::Participant& participant) : participant_(participant) {}

  void declare_mesh(cosim::Mesh mesh) override;
  void declare_mesh(cosim::Mesh mesh, cosim::MeshPart part) override;
  void declare_write(cosim::FieldSpec field) override;
  void declare_read(cosim::FieldSpec field, double default_value) override;
  void write(std::string_view field, std::span<const double> values) override;
  void read(std::string_view field, double dt, std::span<double> values) override;
  void read_increment(std::string_view field, double dt, std::span<double> values) override;
  double max_time_step() const override;
  double window_size() const override;

 private:
  cosim::Participant& participant_;
};

}  // namespace mpm::coupling

#include "cosim/participant.hpp"
#include "mpm/coupling/coupling_channel.hpp"

namespace mpm::coupling {

void ParticipantChannel::declare_mesh(cosim::Mesh mesh) {
  participant_.declare_mesh(std::move(mesh));
}
void ParticipantChannel::declare_mesh(cosim::Mesh mesh, cosim::MeshPart part) {
  participant_.declare_mesh(std::move(mesh), std::move(part));
}
void ParticipantChannel::declare_write(cosim::FieldSpec field) {
  participant_.declare_write(std::move(field));
}
void ParticipantChannel::declare_read(cosim::FieldSpec field, double default_value) {
  participant_.declare_read(std::move(field), default_value);
}
void ParticipantChannel::write(std::string_view field, std::span<const double> values) {
  participant_.write(field, values);
}
void ParticipantChannel::read(std::string_view field, double dt, std::span<double> values) {
  participant_.read(field, values, participant_.reads_vary_within_window() ? 0.5 * dt : 0.0);
}
void ParticipantChannel::read_increment(std::string_view field, double dt,
                                        std::span<double> values) {
  participant_.read_increment(field, dt, values);
}
double ParticipantChannel::max_time_step() const {
  return participant_.max_time_step();
}
double ParticipantChannel::window_size() const {
  return participant_.window_size();
}

}  // namespace mpm::coupling

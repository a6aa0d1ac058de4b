#include "mpm/parallel/particle_migration.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "cosim/error.hpp"

namespace mpm::parallel {

namespace {

// Appends element i of `array` to `bytes`. Every array of Particles holds
// plain values (numbers, std::array, fixed-size Eigen vectors and matrices),
// copied as their bytes.
template <class Array>
void pack(const Array& array, std::size_t i, std::vector<std::byte>& bytes) {
  using T = typename Array::value_type;
  const std::size_t at = bytes.size();
  bytes.resize(at + sizeof(T));
  std::memcpy(bytes.data() + at, &array[i], sizeof(T));
}

// Appends to `array` the element at `bytes`; returns the bytes after it.
template <class Array>
const std::byte* unpack(Array& array, const std::byte* bytes) {
  using T = typename Array::value_type;
  array.emplace_back();
  std::memcpy(static_cast<void*>(&array.back()), bytes, sizeof(T));
  return bytes + sizeof(T);
}

}  // namespace

template <int Dim>
ParticleMigration<Dim>::ParticleMigration(MPI_Comm comm, Owner owner) : owner_(std::move(owner)) {
  MPI_Comm_dup(comm, &comm_);
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &ranks_);
  outgoing_.resize(static_cast<std::size_t>(ranks_));
}

namespace {

// The owner of the cell at x, clamped to the grid.
template <int Dim>
typename ParticleMigration<Dim>::Owner cell_owner(
    const cosim::decomposition::CartesianDecomposition& decomposition, const Vec<Dim>& origin,
    double cell_size) {
  if (decomposition.dimension() != Dim)
    throw cosim::InputError("particle migration: a decomposition of another dimension");
  if (!(cell_size > 0.0)) throw cosim::InputError("particle migration: a cell size <= 0");
  return [decomposition, origin, cell_size](const Vec<Dim>& x) {
    std::array<std::int64_t, 3> cell{0, 0, 0};
    for (int d = 0; d < Dim; ++d) {
      const auto du = static_cast<std::size_t>(d);
      const double s = std::floor((x[d] - origin[d]) / cell_size);
      const auto last = static_cast<double>(decomposition.cells()[du] - 1);
      cell[du] = static_cast<std::int64_t>(std::clamp(std::isfinite(s) ? s : 0.0, 0.0, last));
    }
    return decomposition.owner(cell);
  };
}

}  // namespace

template <int Dim>
ParticleMigration<Dim>::ParticleMigration(
    MPI_Comm comm, const cosim::decomposition::CartesianDecomposition& decomposition,
    const Vec<Dim>& origin, double cell_size)
    : ParticleMigration(comm, cell_owner<Dim>(decomposition, origin, cell_size)) {
  if (ranks_ != decomposition.ranks())
    throw cosim::InputError("particle migration: a decomposition over another number of ranks");
}

template <int Dim>
ParticleMigration<Dim>::~ParticleMigration() {
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
}

template <int Dim>
typename ParticleMigration<Dim>::Moved ParticleMigration<Dim>::migrate(Particles<Dim>& particles) {
  Moved moved;
  const std::size_t n = particles.size();
  destination_.resize(n);
  for (auto& bytes : outgoing_) bytes.clear();
  std::vector<int> sent_points(static_cast<std::size_t>(ranks_), 0);
  for (std::size_t p = 0; p < n; ++p) {
    destination_[p] = owner(particles.position[p]);
    if (destination_[p] == rank_) continue;
    const auto to = static_cast<std::size_t>(destination_[p]);
    particles.for_each_array([&](const auto& array) { pack(array, p, outgoing_[to]); });
    ++sent_points[to];
    ++moved.sent;
  }
  // The points kept, in order.
  std::size_t kept = 0;
  for (std::size_t p = 0; p < n; ++p) {
    if (destination_[p] != rank_) continue;
    if (kept != p) particles.for_each_array([&](auto& array) { array[kept] = array[p]; });
    ++kept;
  }
  particles.for_each_array([&](auto& array) { array.resize(kept); });

  // Only to neighbours, when every rank's points stay among its neighbours.
  int far = 0;
  for (std::size_t r = 0; r < outgoing_.size(); ++r)
    if (!outgoing_[r].empty() &&
        !std::binary_search(neighbours_.begin(), neighbours_.end(), static_cast<int>(r)))
      far = 1;
  if (!neighbours_.empty()) {
    MPI_Allreduce(MPI_IN_PLACE, &far, 1, MPI_INT, MPI_MAX, comm_);
    if (far == 0) return exchange_with_neighbours(particles, sent_points, moved);
  }

  // Bytes to and from every rank, then the points themselves.
  std::vector<int> send_counts(static_cast<std::size_t>(ranks_)),
      receive_counts(static_cast<std::size_t>(ranks_)),
      send_displacements(static_cast<std::size_t>(ranks_)),
      receive_displacements(static_cast<std::size_t>(ranks_)),
      received_points(static_cast<std::size_t>(ranks_));
  send_.clear();
  for (std::size_t r = 0; r < outgoing_.size(); ++r) {
    send_displacements[r] = static_cast<int>(send_.size());
    send_counts[r] = static_cast<int>(outgoing_[r].size());
    send_.insert(send_.end(), outgoing_[r].begin(), outgoing_[r].end());
  }
  moved.bytes_sent = send_.size();
  MPI_Alltoall(sent_points.data(), 1, MPI_INT, received_points.data(), 1, MPI_INT, comm_);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm_);
  int total = 0;
  for (std::size_t r = 0; r < receive_counts.size(); ++r) {
    receive_displacements[r] = total;
    total += receive_counts[r];
  }
  receive_.resize(static_cast<std::size_t>(total));
  MPI_Alltoallv(send_.data(), send_counts.data(), send_displacements.data(), MPI_BYTE,
                receive_.data(), receive_counts.data(), receive_displacements.data(), MPI_BYTE,
                comm_);
  const std::byte* at = receive_.data();
  for (std::size_t r = 0; r < received_points.size(); ++r)
    for (int k = 0; k < received_points[r]; ++k) {
      particles.for_each_array([&](auto& array) { at = unpack(array, at); });
      ++moved.received;
    }
  return moved;
}

template <int Dim>
void ParticleMigration<Dim>::set_neighbours(std::vector<int> neighbours) {
  std::sort(neighbours.begin(), neighbours.end());
  neighbours_ = std::move(neighbours);
}

// The points packed for the neighbours go to them point to point: first
// how many, then their bytes (every point packs to the same size).
template <int Dim>
typename ParticleMigration<Dim>::Moved ParticleMigration<Dim>::exchange_with_neighbours(
    Particles<Dim>& particles, const std::vector<int>& sent_points, Moved moved) {
  const std::size_t k = neighbours_.size();
  std::vector<int> incoming(k, 0);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * k);
  for (std::size_t i = 0; i < k; ++i) {
    requests.emplace_back();
    MPI_Irecv(&incoming[i], 1, MPI_INT, neighbours_[i], 1, comm_, &requests.back());
  }
  for (std::size_t i = 0; i < k; ++i) {
    requests.emplace_back();
    MPI_Isend(&sent_points[static_cast<std::size_t>(neighbours_[i])], 1, MPI_INT, neighbours_[i], 1,
              comm_, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  std::size_t bytes_per_point = 0;
  particles.for_each_array([&](const auto& array) {
    bytes_per_point += sizeof(typename std::decay_t<decltype(array)>::value_type);
  });
  std::vector<std::size_t> offset(k + 1, 0);
  for (std::size_t i = 0; i < k; ++i)
    offset[i + 1] = offset[i] + static_cast<std::size_t>(incoming[i]) * bytes_per_point;
  receive_.resize(offset[k]);
  requests.clear();
  for (std::size_t i = 0; i < k; ++i) {
    if (incoming[i] == 0) continue;
    requests.emplace_back();
    MPI_Irecv(receive_.data() + offset[i], static_cast<int>(offset[i + 1] - offset[i]), MPI_BYTE,
              neighbours_[i], 2, comm_, &requests.back());
  }
  for (const int q : neighbours_) {
    const auto& bytes = outgoing_[static_cast<std::size_t>(q)];
    if (bytes.empty()) continue;
    requests.emplace_back();
    MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, q, 2, comm_,
              &requests.back());
    moved.bytes_sent += bytes.size();
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  const std::byte* at = receive_.data();
  for (std::size_t i = 0; i < k; ++i)
    for (int n = 0; n < incoming[i]; ++n) {
      particles.for_each_array([&](auto& array) { at = unpack(array, at); });
      ++moved.received;
    }
  return moved;
}

template class ParticleMigration<2>;
template class ParticleMigration<3>;

}  // namespace mpm::parallel

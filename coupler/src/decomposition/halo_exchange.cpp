#include "cosim/decomposition/halo_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::decomposition {

HaloExchange::HaloExchange(MPI_Comm comm, const CartesianDecomposition& decomposition, int halo,
                           GhostSides sides)
    : dim_(decomposition.dimension()), halo_(halo) {
  int size = 0;
  MPI_Comm_size(comm, &size);
  if (size != decomposition.ranks())
    throw InputError(fmt::format("a decomposition over {} ranks on a communicator of {}",
                                 decomposition.ranks(), size));
  if (halo < 0) throw InputError(fmt::format("a halo of {} layers", halo));
  std::array<int, 3> dims = decomposition.dims();
  const std::array<int, 3> periods{0, 0, 0};
  MPI_Cart_create(comm, 3, dims.data(), periods.data(), 0, &cart_);
  MPI_Comm_rank(cart_, &rank_);
  block_ = decomposition.block(rank_);
  for (std::size_t d = 0; d < 3; ++d) {
    if (static_cast<int>(d) >= dim_) continue;
    const bool divided = block_.neighbour[2 * d] >= 0 || block_.neighbour[2 * d + 1] >= 0;
    if ((sides == GhostSides::every_side || divided) && block_.cells[d].size() < halo)
      throw InputError(
          fmt::format("rank {} owns {} cells along direction {}, fewer than the halo's {} layers",
                      rank_, block_.cells[d].size(), d, halo));
    const auto ghosts = [&](int side) {
      return sides == GhostSides::every_side || block_.neighbour[2 * d + side] >= 0 ? halo : 0;
    };
    below_[d] = ghosts(0);
    extent_[d] = below_[d] + block_.cells[d].size() + ghosts(1);
  }
}

HaloExchange::~HaloExchange() {
  if (cart_ != MPI_COMM_NULL) MPI_Comm_free(&cart_);
}

std::size_t HaloExchange::padded_size() const {
  return static_cast<std::size_t>(extent_[0] * extent_[1] * extent_[2]);
}

std::size_t HaloExchange::index(std::int64_t i, std::int64_t j, std::int64_t k) const {
  const std::array<std::int64_t, 3> global{i, j, k};
  std::array<std::int64_t, 3> local{0, 0, 0};
  for (std::size_t d = 0; d < 3; ++d)
    local[d] = static_cast<int>(d) < dim_ ? global[d] - block_.cells[d].begin + below_[d] : 0;
  return static_cast<std::size_t>((local[2] * extent_[1] + local[1]) * extent_[0] + local[0]);
}

void HaloExchange::exchange(std::span<double> field, int components) const {
  const std::span<double> fields[1] = {field};
  exchange(fields, components);
}

void HaloExchange::exchange(std::span<const std::span<double>> fields) const {
  exchange(fields, 1);
}

namespace {

// Calls run(field values, buffer values, count) for each row of the slab of
// `halo` layers along direction d from local layer `first`, over the whole
// padded `extent` of the other directions, field after field; the buffer
// position advances through one contiguous buffer.
template <class Run>
void for_each_slab_row(std::span<const std::span<double>> fields, std::size_t per_cell,
                       const std::array<std::int64_t, 3>& extent, std::size_t d, std::int64_t first,
                       std::int64_t halo, double* buffer, Run&& run) {
  std::array<std::int64_t, 3> lo{0, 0, 0}, hi = extent;
  lo[d] = first;
  hi[d] = first + halo;
  for (const std::span<double> field : fields)
    for (std::int64_t k = lo[2]; k < hi[2]; ++k)
      for (std::int64_t j = lo[1]; j < hi[1]; ++j) {
        const auto row = static_cast<std::size_t>((k * extent[1] + j) * extent[0]);
        const auto from = (row + static_cast<std::size_t>(lo[0])) * per_cell;
        const auto count = static_cast<std::size_t>(hi[0] - lo[0]) * per_cell;
        run(field.data() + from, buffer, count);
        buffer += count;
      }
}

}  // namespace

void HaloExchange::check(std::span<const std::span<double>> fields, int components) const {
  for (const std::span<double> field : fields)
    if (components < 1 || field.size() != padded_size() * static_cast<std::size_t>(components))
      throw InputError(
          fmt::format("a halo exchange of {} values for {} padded cells x {} components",
                      field.size(), padded_size(), components));
}

void HaloExchange::exchange(std::span<const std::span<double>> fields, int components) const {
  check(fields, components);
  values_sent_ = 0;
  if (halo_ == 0 || fields.empty()) return;
  const auto per_cell = static_cast<std::size_t>(components);
  for (std::size_t d = 0; d < static_cast<std::size_t>(dim_); ++d) {
    const std::int64_t owned = block_.cells[d].size();
    // Towards the upper neighbour: its lower ghosts get my last owned layers;
    // then towards the lower one.
    for (int side = 0; side < 2; ++side) {
      const std::int64_t send_first = side == 0 ? below_[d] + owned - halo_ : below_[d];
      const std::int64_t receive_first = side == 0 ? 0 : below_[d] + owned;
      transfer(fields, per_cell, d, side == 0, send_first, receive_first,
               [](double* field, const double* buffer, std::size_t n) {
                 std::copy_n(buffer, n, field);
               });
    }
  }
}

void HaloExchange::accumulate(std::span<const std::span<double>> fields) const {
  check(fields, 1);
  values_sent_ = 0;
  if (halo_ == 0 || fields.empty()) return;
  // Each direction carries the whole padded extent of the others, so what
  // lies in an edge or corner ghost reaches its owner through the block
  // that shares a face with both.
  for (std::size_t d = 0; d < static_cast<std::size_t>(dim_); ++d) {
    const std::int64_t owned = block_.cells[d].size();
    // My upper ghosts to the upper neighbour's first owned layers; then my
    // lower ghosts to the lower neighbour's last owned layers.
    for (int side = 0; side < 2; ++side) {
      const std::int64_t send_first = side == 0 ? below_[d] + owned : 0;
      const std::int64_t receive_first = side == 0 ? below_[d] : below_[d] + owned - halo_;
      transfer(fields, 1, d, side == 0, send_first, receive_first,
               [](double* field, const double* buffer, std::size_t n) {
                 for (std::size_t v = 0; v < n; ++v) field[v] += buffer[v];
               });
    }
  }
}

template <class Receive>
void HaloExchange::transfer(std::span<const std::span<double>> fields, std::size_t per_cell,
                            std::size_t d, bool upward, std::int64_t send_first,
                            std::int64_t receive_first, Receive&& receive) const {
  std::size_t slab_values = static_cast<std::size_t>(halo_) * per_cell * fields.size();
  for (std::size_t e = 0; e < 3; ++e)
    if (e != d) slab_values *= static_cast<std::size_t>(extent_[e]);
  send_.resize(slab_values);
  receive_.resize(slab_values);
  const auto count = static_cast<int>(slab_values);
  const int to = block_.neighbour[2 * d + (upward ? 1 : 0)];
  const int from = block_.neighbour[2 * d + (upward ? 0 : 1)];
  if (to >= 0) {
    for_each_slab_row(
        fields, per_cell, extent_, d, send_first, halo_, send_.data(),
        [](const double* field, double* buffer, std::size_t n) { std::copy_n(field, n, buffer); });
    values_sent_ += slab_values;
  }
  MPI_Sendrecv(send_.data(), to >= 0 ? count : 0, MPI_DOUBLE, to >= 0 ? to : MPI_PROC_NULL,
               static_cast<int>(d), receive_.data(), from >= 0 ? count : 0, MPI_DOUBLE,
               from >= 0 ? from : MPI_PROC_NULL, static_cast<int>(d), cart_, MPI_STATUS_IGNORE);
  if (from >= 0)
    for_each_slab_row(
        fields, per_cell, extent_, d, receive_first, halo_, receive_.data(),
        [&receive](double* field, double* buffer, std::size_t n) { receive(field, buffer, n); });
}

}  // namespace cosim::decomposition

#include "cosim/decomposition/halo_exchange.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "cosim/error.hpp"

namespace cosim::decomposition {

HaloExchange::HaloExchange(MPI_Comm comm, const CartesianDecomposition& decomposition, int halo)
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
    if (block_.cells[d].size() < halo)
      throw InputError(
          fmt::format("rank {} owns {} cells along direction {}, fewer than the halo's {} layers",
                      rank_, block_.cells[d].size(), d, halo));
    extent_[d] = block_.cells[d].size() + 2 * halo;
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
    local[d] = static_cast<int>(d) < dim_ ? global[d] - block_.cells[d].begin + halo_ : 0;
  return static_cast<std::size_t>((local[2] * extent_[1] + local[1]) * extent_[0] + local[0]);
}

void HaloExchange::exchange(std::span<double> field, int components) const {
  const std::span<double> fields[1] = {field};
  exchange(fields, components);
}

void HaloExchange::exchange(std::span<const std::span<double>> fields) const {
  exchange(fields, 1);
}

void HaloExchange::exchange(std::span<const std::span<double>> fields, int components) const {
  const auto per_cell = static_cast<std::size_t>(components);
  for (const std::span<double> field : fields)
    if (components < 1 || field.size() != padded_size() * per_cell)
      throw InputError(
          fmt::format("a halo exchange of {} values for {} padded cells x {} components",
                      field.size(), padded_size(), components));
  values_sent_ = 0;
  if (halo_ == 0 || fields.empty()) return;
  for (int d = 0; d < dim_; ++d) {
    const auto du = static_cast<std::size_t>(d);
    // The slab of `halo_` layers along d starting at local layer `first`,
    // over the whole padded extent of the other directions, field after field.
    auto slab = [&](std::int64_t first, std::vector<double>* out, const std::vector<double>* in) {
      std::size_t n = 0;
      std::array<std::int64_t, 3> lo{0, 0, 0}, hi = extent_;
      lo[du] = first;
      hi[du] = first + halo_;
      for (const std::span<double> field : fields)
        for (std::int64_t k = lo[2]; k < hi[2]; ++k)
          for (std::int64_t j = lo[1]; j < hi[1]; ++j) {
            const auto row = static_cast<std::size_t>((k * extent_[1] + j) * extent_[0]);
            const auto from = (row + static_cast<std::size_t>(lo[0])) * per_cell;
            const auto count = static_cast<std::size_t>(hi[0] - lo[0]) * per_cell;
            if (out)
              std::copy_n(field.begin() + static_cast<std::ptrdiff_t>(from), count,
                          out->begin() + static_cast<std::ptrdiff_t>(n));
            if (in)
              std::copy_n(in->begin() + static_cast<std::ptrdiff_t>(n), count,
                          field.begin() + static_cast<std::ptrdiff_t>(from));
            n += count;
          }
    };
    std::size_t slab_values = static_cast<std::size_t>(halo_) * per_cell * fields.size();
    for (std::size_t e = 0; e < 3; ++e)
      if (e != du) slab_values *= static_cast<std::size_t>(extent_[e]);
    send_.resize(slab_values);
    receive_.resize(slab_values);
    const auto count = static_cast<int>(slab_values);
    const std::int64_t owned = block_.cells[du].size();
    // Towards the upper neighbour: its lower ghosts get my last owned layers.
    for (int side = 0; side < 2; ++side) {
      const int to = block_.neighbour[2 * du + (side == 0 ? 1 : 0)];
      const int from = block_.neighbour[2 * du + (side == 0 ? 0 : 1)];
      const std::int64_t send_first = side == 0 ? owned : halo_;
      const std::int64_t receive_first = side == 0 ? 0 : owned + halo_;
      if (to >= 0) {
        slab(send_first, &send_, nullptr);
        values_sent_ += slab_values;
      }
      MPI_Sendrecv(send_.data(), to >= 0 ? count : 0, MPI_DOUBLE, to >= 0 ? to : MPI_PROC_NULL, d,
                   receive_.data(), from >= 0 ? count : 0, MPI_DOUBLE,
                   from >= 0 ? from : MPI_PROC_NULL, d, cart_, MPI_STATUS_IGNORE);
      if (from >= 0) slab(receive_first, nullptr, &receive_);
    }
  }
}

}  // namespace cosim::decomposition

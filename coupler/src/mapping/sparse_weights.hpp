#pragma once

#include <cstddef>
#include <vector>

#include "mapping/operator.hpp"

// Helpers to build compressed row-major weights directly (no triplets).
namespace cosim::mapping::detail {

// Compressed rows × cols weights with room for `nonzeros` entries; the caller
// fills outerIndexPtr() (rows + 1 offsets), innerIndexPtr() and valuePtr().
// Throws InputError when the operator is too large for 32-bit indices.
Weights allocate_weights(std::size_t rows, std::size_t cols, std::size_t nonzeros);

// Divides each row by its sum; returns the rows whose sum is zero (left empty
// or zero).
std::vector<std::size_t> normalise_rows(Weights& weights);

// Scales column c by scale[c].
void scale_columns(Weights& weights, const std::vector<double>& scale);

Weights transposed(const Weights& weights);

}  // namespace cosim::mapping::detail

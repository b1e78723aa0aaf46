#pragma once
/// \file
/// Keyed pseudo-random permutations of [0, n): the cmj sampler's row, column and cell shuffles,
/// and the shuffle that decorrelates a path's dimension pairs (sample_dimensions.cpp). Internal
/// to the library.

#include <cstdint>

namespace raylab::detail {

/// Element `i` (0 <= i < n) of a pseudo-random permutation of [0, n) keyed by `key`: the same
/// (n, key) always gives the same permutation, different keys independent-looking ones.
int permute(int i, int n, std::uint64_t key);

}  // namespace raylab::detail

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

/// Element `i` of a keyed permutation of [0, n) that costs a few multiplications where permute
/// costs a few dozen hashes: for shuffling sample indices against each other many times per
/// sample (a path's dimension pairs), where what matters is that the indices of two pairs look
/// unrelated, not that every one of the n! orders is equally likely.
int shuffle(int i, int n, std::uint64_t key);

}  // namespace raylab::detail

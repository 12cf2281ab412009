// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H

#include <CGAL/Lex_optimal_chains/internal/Large_array_allocator.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Sorts 64-bit words (a 32-bit key in the high half, a payload in the low half) by their
// high 32 bits: LSD radix sort, 4 stable passes of 8 bits, `buffer` as scratch space.
template <class Vector> // of std::uint64_t
void radix_sort_high_words(Vector& v, Vector& buffer)
{
  buffer.resize(v.size());
  for(int shift = 32; shift < 64; shift += 8) {
    std::size_t count[257] = {0};
    for(std::uint64_t x : v) ++count[((x >> shift) & 0xff) + 1];
    for(int d = 0; d < 256; ++d) count[d + 1] += count[d];
    for(std::uint64_t x : v) buffer[count[(x >> shift) & 0xff]++] = x;
    v.swap(buffer);
  }
}

// Counting sort of the items 0, ..., n - 1 by `key(i)`, in [0, number_of_keys): calls
// `place(i, position)` for every item, in increasing order of the items, the positions of key k
// being first[k], ..., first[k + 1] - 1; returns `first` (number_of_keys + 1 offsets).
template <class Key, class Place>
Large_vector<std::uint32_t> counting_sort_by_key(std::size_t number_of_keys, std::uint32_t n, const Key& key,
                                                 const Place& place)
{
  Large_vector<std::uint32_t> first(number_of_keys + 1, 0);
  for(std::uint32_t i = 0; i < n; ++i) ++first[key(i) + 1];
  for(std::size_t k = 0; k < number_of_keys; ++k) first[k + 1] += first[k];
  Large_vector<std::uint32_t> next(first.begin(), first.end() - 1);
  for(std::uint32_t i = 0; i < n; ++i) place(i, next[key(i)]++);
  return first;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Sorts 64-bit words (a 32-bit key in the high half, a payload in the low half) by their
// high 32 bits: LSD radix sort, 4 stable passes of 8 bits, `buffer` as scratch space.
inline void radix_sort_high_words(std::vector<std::uint64_t>& v, std::vector<std::uint64_t>& buffer)
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

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_RADIX_SORT_H

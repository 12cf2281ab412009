// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DENSE_NUMBERS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DENSE_NUMBERS_H

// Dense numbers 0, 1, ... for a few keys among many indices, in the order of their insertion:
// the roots of the components of the contraction (a few thousandths of the cells), or the
// facets of a surface met around its non-manifold edges. A Kruskal pass over the sorted facets
// looks up the components of both cells of every facet; an open-addressing table over the
// roots stays in cache, where an array over all the cells, or disjoint sets over them, would
// not.

#include <CGAL/assertions.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

class Dense_numbers
{
public:
  // Prepares for at most `n` keys.
  explicit Dense_numbers(std::size_t n = 0)
  {
    bits_ = 4;
    while((std::size_t(1) << bits_) < 2 * n) ++bits_;
    slots_.assign(std::size_t(1) << bits_, empty);
    keys_.reserve(n);
    capacity_ = n;
  }

  // The number of `key`, which is given the next one if it has none.
  std::uint32_t insert(std::uint32_t key)
  {
    std::size_t s = slot_of(key);
    for(; slots_[s] != empty; s = (s + 1) & mask())
      if(std::uint32_t(slots_[s] >> 32) == key) return std::uint32_t(slots_[s]);
    CGAL_precondition(keys_.size() < capacity_); // at most n keys: a slot stays free
    const std::uint32_t number = std::uint32_t(keys_.size());
    slots_[s] = (std::uint64_t(key) << 32) | number;
    keys_.push_back(key);
    return number;
  }

  // The number of `key`, which must have been inserted.
  std::uint32_t operator[](std::uint32_t key) const
  {
    for(std::size_t s = slot_of(key);; s = (s + 1) & mask()) {
      if(slots_[s] == empty) CGAL_error_msg("Dense_numbers: a key that was not inserted");
      if(std::uint32_t(slots_[s] >> 32) == key) return std::uint32_t(slots_[s]);
    }
  }

  std::uint32_t key(std::uint32_t number) const { return keys_[number]; }
  std::size_t size() const { return keys_.size(); }

private:
  // a slot holds (key << 32) | number; no key is 2^32 - 1 with number 2^32 - 1
  static constexpr std::uint64_t empty = ~std::uint64_t(0);
  std::size_t mask() const { return slots_.size() - 1; }
  // Fibonacci hashing: the high bits of the product mix all the bits of the key
  std::size_t slot_of(std::uint32_t key) const
  {
    return std::size_t((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }

  int bits_;
  std::size_t capacity_;
  std::vector<std::uint64_t> slots_;
  std::vector<std::uint32_t> keys_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_DENSE_NUMBERS_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_ZEROED_BYTES_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_ZEROED_BYTES_H

// An array of bytes that starts at zero, for the ranks of disjoint sets: only the roots that
// get linked ever have a rank above zero, and after the contraction of the cells across their
// largest facets these are a few thousand among tens of millions of elements. The array is
// allocated with `calloc`, which takes large blocks from the system as fresh pages that are
// already zero: the pages that are never written are never touched, so they cost neither
// memory nor page faults. With an allocator that zeroes the block itself, the array just
// costs what a zeroed vector costs.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

class Zeroed_bytes
{
public:
  Zeroed_bytes() = default;

  // n bytes at zero (the previous ones are released)
  void assign(std::size_t n)
  {
    bytes_.reset();
    if(n == 0) return;
    bytes_.reset(static_cast<std::uint8_t*>(std::calloc(n, 1)));
    if(!bytes_) throw std::bad_alloc();
  }

  std::uint8_t& operator[](std::size_t i) { return bytes_.get()[i]; }
  std::uint8_t operator[](std::size_t i) const { return bytes_.get()[i]; }
  const std::uint8_t* data() const { return bytes_.get(); }

private:
  struct Free
  {
    void operator()(std::uint8_t* p) const { std::free(p); }
  };
  std::unique_ptr<std::uint8_t[], Free> bytes_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_ZEROED_BYTES_H

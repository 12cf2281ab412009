// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PREFETCH_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PREFETCH_H

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Hints that the cache line of `p` will be read soon. The loops over millions of triangles
// and cells know their random reads a few iterations ahead; fetching them early overlaps
// the cache misses. A performance hint only (no effect without GCC builtins).
inline void prefetch_address(const void* p)
{
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// Both cache lines that an object may straddle (cells of 72 bytes, vertices of 40).
template <class T>
void prefetch_object(const T* p)
{
  prefetch_address(p);
  prefetch_address(reinterpret_cast<const char*>(p) + sizeof(T) - 1);
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PREFETCH_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UNION_FIND_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UNION_FIND_H

#include <CGAL/Lex_optimal_chains/internal/Large_array_allocator.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Zeroed_bytes.h>

#include <CGAL/assertions.h>

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Whether the parent pointers `parent(x)` of the elements [0, n) lead every element to a root
// (an element that is its own parent), with no cycle: O(n), each element walked once.
template <class Parent>
bool is_forest_of_parents(std::size_t n, const Parent& parent)
{
  using Index = std::uint32_t;
  constexpr Index unknown = Index(-1), rooted = Index(-2);
  std::vector<Index> state(n, unknown); // or the element whose walk reached it
  for(Index x = 0; x < n; ++x) {
    Index y = x;
    while(state[y] == unknown && parent(y) != y) { state[y] = x; y = parent(y); }
    if(state[y] == x) return false; // back on this walk: a cycle
    for(Index z = x; state[z] == x; z = parent(z)) state[z] = rooted; // it ends at a root
    state[y] = rooted;
  }
  return true;
}

// Disjoint sets over the dense indices [0, n): path halving and union by rank.
// Ranks (at most log2 n < 256) are bytes in a separate array, so that `find` touches one
// 32-bit word per step; the bytes of the elements that are never linked as roots are never
// touched (internal/Zeroed_bytes.h).
class Union_find
{
public:
  using Index = std::uint32_t;

  explicit Union_find(std::size_t n = 0) { reset(n); }

  void reset(std::size_t n)
  {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), Index(0));
    rank_.assign(n); // zero, untouched until a root is linked
  }

  std::size_t size() const { return parent_.size(); }

  Index find(Index x)
  {
    CGAL_precondition(x < parent_.size());
    for(;;) {
      const Index p = parent_[x];
      if(p == x) return x;
      const Index gp = parent_[p];
      if(gp == p) return p; // nothing to shorten: no write
      parent_[x] = gp;
      x = gp;
    }
  }

  // Sets the parent of `x` (which must be alone) to `p`, for `set_forest_of_parents()`.
  void set_parent(Index x, Index p)
  {
    CGAL_precondition(parent_[x] == x && p < parent_.size());
    parent_[x] = p;
  }

  // Makes the sets of the parents given by `set_parent()`, which form a forest but for cycles
  // of two elements (x -> y -> x), broken at the element of larger index, which becomes a
  // root. The ranks stay 0: they only balance the later links.
  void set_forest_of_parents()
  {
    const Index n = Index(parent_.size());
    constexpr Index ahead = 16; // the parents' parents, read at random, are fetched early
    for(Index x = 0; x < n; ++x) {
      if(x + ahead < n) prefetch_address(parent_.data() + parent_[x + ahead]);
      const Index p = parent_[x];
      // p < x: p's parent is final already, and it is x only if p is the smaller of a pair
      if(p < x && parent_[p] == x) parent_[x] = x;
    }
    CGAL_assertion(is_forest()); // a cycle would make find() loop forever
  }

  // whether the parent pointers lead every element to a root (no cycle)
  bool is_forest() const
  {
    return is_forest_of_parents(parent_.size(), [this](Index x) { return parent_[x]; });
  }

  // Points every element directly at its root. Full path compression from each element, so
  // that every element is written once (the trees of `set_forest_of_parents()` can be
  // hundreds deep).
  void flatten()
  {
    std::vector<Index> path;
    const Index n = Index(parent_.size());
    constexpr Index ahead = 16; // the parents, read at random, are fetched early
    for(Index x = 0; x < n; ++x) {
      if(x + ahead < n) prefetch_address(parent_.data() + parent_[x + ahead]);
      path.clear();
      Index y = x;
      for(;;) { // up to an element that is a root or points at one
        const Index p = parent_[y];
        if(p == y || parent_[p] == p) break;
        path.push_back(y);
        y = p;
      }
      const Index root = parent_[y];
      for(const Index z : path) parent_[z] = root;
    }
  }

  // `find(x)` when every element points directly at its root (after `flatten()`, before any
  // link): reads one word.
  Index find_in_flat(Index x) const
  {
    CGAL_precondition(parent_[parent_[x]] == parent_[x]);
    return parent_[x];
  }

  // Hints that `find(x)` will be called soon (the parent array is read at random).
  void prefetch(Index x) const
  {
    prefetch_address(parent_.data() + x);
    prefetch_address(rank_.data() + x); // read if x is a root that gets linked
  }

  // Hints that `find_in_flat(x)` will be called soon: no link follows, the rank is not read.
  void prefetch_parent(Index x) const { prefetch_address(parent_.data() + x); }

  // Links the two roots `a` and `b` (which must be roots) and returns the new root.
  Index link_roots(Index a, Index b)
  {
    CGAL_precondition(parent_[a] == a && parent_[b] == b);
    if(a == b) return a;
    if(rank_[a] < rank_[b]) std::swap(a, b);
    parent_[b] = a;
    if(rank_[a] == rank_[b]) ++rank_[a];
    return a;
  }

  Index unite(Index a, Index b) { return link_roots(find(a), find(b)); }

private:
  Large_vector<Index> parent_;
  Zeroed_bytes rank_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UNION_FIND_H

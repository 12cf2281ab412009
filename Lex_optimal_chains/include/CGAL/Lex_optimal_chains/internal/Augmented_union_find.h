// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H

// Algorithm 9 of the thesis: disjoint sets whose tree links carry a value of a coefficient
// group. `value[x]` is the value of the directed path from x to its parent, so the sum of
// the values from x to its root is the value of the path from x to the root (a root has
// value zero). Path halving adds up the values it shortcuts; union by rank negates the link
// value when the link goes the other way.

#include <CGAL/assertions.h>

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

template <class Arithmetic>
class Augmented_union_find
{
public:
  using Index = std::uint32_t;
  using Value = typename Arithmetic::Value;

  explicit Augmented_union_find(std::size_t n = 0) { reset(n); }

  // MakeSet* for the elements [0, n)
  void reset(std::size_t n)
  {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), Index(0));
    rank_.assign(n, 0);
    value_.assign(n, Arithmetic::zero());
  }

  std::size_t size() const { return parent_.size(); }

  // FindSet*: the root of x and the value of the path from x to it.
  std::pair<Index, Value> find(Index x)
  {
    CGAL_precondition(x < parent_.size());
    Value g = Arithmetic::zero();
    while(parent_[x] != x) {
      const Index p = parent_[x];
      // x now skips p: its link value becomes the value of the path x -> p -> parent(p)
      value_[x] = Arithmetic::add(value_[x], value_[p]);
      parent_[x] = parent_[p];
      g = Arithmetic::add(g, value_[x]);
      x = parent_[x];
    }
    return {x, g};
  }

  // LinkSet*: joins the roots r1 and r2 (distinct) so that the path from r1 to r2 has value
  // `delta`; returns the new root.
  Index link_roots(Index r1, Index r2, Value delta)
  {
    CGAL_precondition(r1 != r2 && parent_[r1] == r1 && parent_[r2] == r2);
    if(rank_[r1] > rank_[r2]) { // r2 goes under r1: the path r2 -> r1 has value -delta
      parent_[r2] = r1;
      value_[r2] = Arithmetic::negate(delta);
      return r1;
    }
    parent_[r1] = r2;
    value_[r1] = delta;
    if(rank_[r1] == rank_[r2]) ++rank_[r2];
    return r2;
  }

  void prefetch(Index x) const
  {
#if defined(__GNUC__)
    __builtin_prefetch(parent_.data() + x);
    __builtin_prefetch(value_.data() + x);
#else
    (void)x;
#endif
  }

private:
  std::vector<Index> parent_;
  std::vector<std::uint8_t> rank_;
  std::vector<Value> value_;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H

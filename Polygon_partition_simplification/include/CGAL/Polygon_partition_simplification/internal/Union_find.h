// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_UNION_FIND_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_UNION_FIND_H

// Disjoint sets of the indices 0 to n - 1 (points, lines, edges of a partition), the one
// union-find of the package. The elements are dense indices, so the sets are two arrays (parent,
// size) that reset() reuses from pass to pass; CGAL::Union_find is made for handles: it allocates
// one node per element and cannot be reset, and its root after a union is chosen by set size
// only, whereas some callers here need a given root (see below).
//
// find() halves the path it walks (every node visited gets its grandparent as parent). The root
// of a union, which is the representative of the united set, is chosen by the caller:
// - unite(x, y): union by size, the root of the larger set stays the root (on equal sizes, the
//   smaller of the two roots): for callers that only ask whether two elements are in one set;
// - unite_at_smallest(x, y): the smaller of the two roots stays the root, so that, with this
//   union only, the representative of every set is its smallest element (callers that number
//   the sets or keep the state of a set at its representative in the order of the indices);
// - unite_into(x, y): the root of the set of y stays the root (callers whose output depends on
//   the order of the representatives, which this rule fixes).
// All three are deterministic, and sizes are kept by all, so that they may be mixed.

#include <CGAL/assertions.h>

#include <cstddef>
#include <numeric>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

template <class Index = std::size_t>
class Union_find
{
  static_assert(std::is_integral<Index>::value && std::is_unsigned<Index>::value, "Index: an unsigned integer type");

public:
  explicit Union_find(std::size_t n = 0) { reset(n); }

  // n sets of one element each, 0 to n - 1 (the memory of the arrays is kept)
  void reset(std::size_t n)
  {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), Index(0));
    size_.assign(n, Index(1));
    sets_ = n;
  }

  std::size_t number_of_elements() const { return parent_.size(); }
  std::size_t number_of_sets() const { return sets_; }

  // the representative (root) of the set of x
  Index find(Index x)
  {
    CGAL_precondition(std::size_t(x) < parent_.size());
    while(parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  bool same_set(Index x, Index y) { return find(x) == find(y); }

  // unites the sets of x and y, by size; false if they are one set already
  bool unite(Index x, Index y)
  {
    x = find(x);
    y = find(y);
    if(x == y) return false;
    if(size_[x] < size_[y] || (size_[x] == size_[y] && y < x)) link(x, y);
    else link(y, x);
    return true;
  }

  // unites the sets of x and y under the smaller of their two roots; false if they are one set
  bool unite_at_smallest(Index x, Index y)
  {
    x = find(x);
    y = find(y);
    if(x == y) return false;
    if(x < y) link(y, x);
    else link(x, y);
    return true;
  }

  // unites the set of x into that of y, whose root stays the root; false if they are one set
  bool unite_into(Index x, Index y)
  {
    x = find(x);
    y = find(y);
    if(x == y) return false;
    link(x, y);
    return true;
  }

private:
  // root `child` below root `root`
  void link(Index child, Index root)
  {
    parent_[child] = root;
    size_[root] += size_[child];
    --sets_;
  }

  std::vector<Index> parent_;
  std::vector<Index> size_;
  std::size_t sets_ = 0;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_UNION_FIND_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H

// Algorithm 9 of the thesis: disjoint sets whose tree links carry a value of a coefficient
// group. `value[x]` is the value of the directed path from x to its parent, so the sum of
// the values from x to its root is the value of the path from x to the root (a root has
// value zero). Path halving adds up the values it shortcuts; union by rank negates the link
// value when the link goes the other way. Defined for Z2_arithmetic, Z2_word_arithmetic and
// Integer_arithmetic.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Chain_arithmetic.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>
#include <CGAL/Lex_optimal_chains/internal/Zeroed_bytes.h>

#include <CGAL/assertions.h>

#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// How the nodes are stored: the parent and the value of its link side by side, so that a
// step of `find` reads one word (Z2: the value is the top bit of the parent index), one
// 8-byte node (integers: a 32-bit value, range-checked) or one 16-byte node (64 chains over
// Z2: a 64-bit value, 4 bytes of padding).
template <class Arithmetic>
struct Augmented_node;

template <>
struct Augmented_node<Z2_arithmetic>
{
  std::uint32_t word; // parent | value << 31
  static constexpr std::uint32_t max_size = std::uint32_t(1) << 31;
  std::uint32_t parent() const { return word & 0x7fffffffu; }
  std::uint8_t value() const { return std::uint8_t(word >> 31); }
  void set(std::uint32_t parent, std::uint8_t value) { word = parent | (std::uint32_t(value) << 31); }
};

template <>
struct Augmented_node<Z2_word_arithmetic>
{
  std::uint64_t link_value;
  std::uint32_t parent_index;
  static constexpr std::uint32_t max_size = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t parent() const { return parent_index; }
  std::uint64_t value() const { return link_value; }
  void set(std::uint32_t parent, std::uint64_t value)
  {
    parent_index = parent;
    link_value = value;
  }
};

template <>
struct Augmented_node<Integer_arithmetic>
{
  std::uint32_t parent_index;
  std::int32_t link_value;
  static constexpr std::uint32_t max_size = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t parent() const { return parent_index; }
  std::int64_t value() const { return link_value; }
  void set(std::uint32_t parent, std::int64_t value)
  {
    if(value > std::numeric_limits<std::int32_t>::max() || value < std::numeric_limits<std::int32_t>::min())
      throw Input_error(Input_error_code::TOO_LARGE, "an intersection product overflows 32-bit integers");
    parent_index = parent;
    link_value = std::int32_t(value);
  }
};

template <class Arithmetic>
class Augmented_union_find
{
public:
  using Index = std::uint32_t;
  using Value = typename Arithmetic::Value;
  using Node = Augmented_node<Arithmetic>;

  explicit Augmented_union_find(std::size_t n = 0) { reset(n); }

  // MakeSet* for the elements [0, n)
  void reset(std::size_t n)
  {
    if(n > Node::max_size)
      throw Input_error(Input_error_code::TOO_LARGE, "too many elements for the augmented disjoint sets");
    nodes_.resize(n);
    for(std::size_t i = 0; i < n; ++i) nodes_[i].set(Index(i), Arithmetic::zero());
    rank_.assign(n); // zero, untouched until a root is linked
  }

  std::size_t size() const { return nodes_.size(); }

  // FindSet*: the root of x and the value of the path from x to it.
  std::pair<Index, Value> find(Index x)
  {
    CGAL_precondition(x < nodes_.size());
    Value g = Arithmetic::zero();
    for(;;) {
      Node& n = nodes_[x];
      const Index p = n.parent();
      if(p == x) return {x, g};
      const Node& np = nodes_[p];
      const Index gp = np.parent();
      if(gp == p) return {p, Arithmetic::add(g, n.value())}; // nothing to shorten: no write
      // x now skips p: its link value becomes the value of the path x -> p -> parent(p)
      const Value v = Arithmetic::add(n.value(), np.value());
      n.set(gp, v);
      g = Arithmetic::add(g, v);
      x = gp;
    }
  }

  // LinkSet*: joins the roots r1 and r2 (distinct) so that the path from r1 to r2 has value
  // `delta`; returns the new root.
  Index link_roots(Index r1, Index r2, Value delta)
  {
    CGAL_precondition(r1 != r2 && nodes_[r1].parent() == r1 && nodes_[r2].parent() == r2);
    if(rank_[r1] > rank_[r2]) { // r2 goes under r1: the path r2 -> r1 has value -delta
      nodes_[r2].set(r1, Arithmetic::negate(delta));
      return r1;
    }
    nodes_[r1].set(r2, delta);
    if(rank_[r1] == rank_[r2]) ++rank_[r2];
    return r2;
  }

  // Sets the parent of `x` (which must be alone) to `p`, for `set_forest_of_parents()`.
  void set_parent(Index x, Index p)
  {
    CGAL_precondition(nodes_[x].parent() == x && p < nodes_.size());
    nodes_[x].set(p, Arithmetic::zero());
  }

  // Builds the sets of the parents given by `set_parent()`, which form a forest but for cycles
  // of two elements (x -> y -> x), broken at the element of larger index, which becomes a
  // root; `value(x, p)` is the value of the path from x to its parent p. The ranks stay 0: they
  // only balance the later links, and every value stays right whatever they are.
  template <class LinkValue>
  void set_forest_of_parents(const LinkValue& value)
  {
    for(Index x = 0; x < nodes_.size(); ++x) {
      const Index p = nodes_[x].parent();
      if(p == x) continue;
      // p < x: p's parent is final already, and it is x only if p is the smaller of a pair
      if(p < x && nodes_[p].parent() == x) nodes_[x].set(x, Arithmetic::zero());
      else nodes_[x].set(p, value(x, p));
    }
    CGAL_assertion(is_forest()); // a cycle would make find() loop forever
  }

  // whether the parent pointers lead every element to a root (no cycle)
  bool is_forest() const
  {
    return is_forest_of_parents(nodes_.size(), [this](Index x) { return nodes_[x].parent(); });
  }

  // `find(x)` when every element points directly at its root (after `flatten()`, before any
  // link): reads one node.
  std::pair<Index, Value> find_in_flat(Index x) const
  {
    const Node& n = nodes_[x];
    CGAL_precondition(nodes_[n.parent()].parent() == n.parent());
    return n.parent() == x ? std::make_pair(x, Arithmetic::zero()) : std::make_pair(n.parent(), Value(n.value()));
  }

  // Points every element directly at its root: a later `find` reads two nodes. Full path
  // compression, top down: each walk stops at the first element that points at its root
  // already, so every element is written once, whatever the depth of the trees (those of
  // `set_forest_of_parents()` can be hundreds deep).
  void flatten()
  {
    std::vector<Index> path;
    const Index n = Index(nodes_.size());
    constexpr Index ahead = 16; // the parents, read at random, are fetched early
    for(Index x = 0; x < n; ++x) {
      if(x + ahead < n) prefetch_address(nodes_.data() + nodes_[x + ahead].parent());
      path.clear();
      Index y = x;
      for(;;) { // up to an element that is a root or points at one
        const Index p = nodes_[y].parent();
        if(p == y || nodes_[p].parent() == p) break;
        path.push_back(y);
        y = p;
      }
      // y is flat: its root and the value of the path to it
      const Index root = nodes_[y].parent();
      Value to_root = root == y ? Arithmetic::zero() : Value(nodes_[y].value());
      for(std::size_t i = path.size(); i-- > 0;) { // each element's parent is flat by now
        Node& node = nodes_[path[i]];
        to_root = Arithmetic::add(Value(node.value()), to_root);
        node.set(root, to_root);
      }
    }
  }

  void prefetch(Index x) const
  {
    prefetch_address(nodes_.data() + x);
    prefetch_address(rank_.data() + x); // read if x is a root that gets linked
  }

private:
  std::vector<Node> nodes_;
  Zeroed_bytes rank_; // at most log2 n < 256
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_AUGMENTED_UNION_FIND_H

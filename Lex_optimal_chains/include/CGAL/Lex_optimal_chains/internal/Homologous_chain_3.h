// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HOMOLOGOUS_CHAIN_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HOMOLOGOUS_CHAIN_3_H

// Algorithm 10 of the thesis on the sorted dual graph of a 3D Delaunay triangulation
// completed to S^3: the lexicographic optimal 2-chain homologous to a given chain Gamma0,
// absolute or relative to a set B of triangles, with the augmented disjoint sets of
// Algorithm 9.
//
// Orientation convention: the dual edge of a record goes from its owner cell to the other
// cell, and crosses the triangle oriented outward of the owner; the intersection product of
// a chain with that edge is the chain's coefficient on that oriented triangle. (The dual
// boundary is then minus the transposed primal boundary: a global sign, which leaves the
// orthogonality relations of Lemma 4.34, hence the algorithm, unchanged.)
//
// The infinite cells all stand for the infinite vertex: their triangles are larger than all
// finite ones and carry no coefficient of Gamma0 (which is finite), so Algorithm 10 would
// unite them first with zero values; they start as one set.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Augmented_union_find.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Sparse values on records, looked up by record code; a bit per owner cell answers most
// lookups from a small array that stays in cache.
template <class Value>
class Record_values
{
public:
  explicit Record_values(std::size_t cells = 0) : owners_((cells + 63) / 64, 0) {}

  // adds v to the value of the record `code`
  template <class Arithmetic>
  void add(std::uint32_t code, Value v)
  {
    auto& x = values_[code];
    x = Arithmetic::add(x, v);
    owners_[(code >> 2) / 64] |= std::uint64_t(1) << ((code >> 2) % 64);
  }

  bool may_contain(std::uint32_t owner) const { return owners_[owner / 64] >> (owner % 64) & 1; }

  // the value of `code`, or `zero` if there is none
  Value get(std::uint32_t code, Value zero) const
  {
    if(!may_contain(code >> 2)) return zero;
    const auto it = values_.find(code);
    return it == values_.end() ? zero : it->second;
  }

  bool contains(std::uint32_t code) const
  {
    return may_contain(code >> 2) && values_.count(code) != 0;
  }

  const std::unordered_map<std::uint32_t, Value>& values() const { return values_; }

private:
  std::vector<std::uint64_t> owners_;
  std::unordered_map<std::uint32_t, Value> values_;
};

// Algorithm 10. `gamma0` holds Gamma0 on records (in their orientation); the records in
// `relative` (the triangles of B) are not edges of the dual graph. Returns the optimal chain
// as (record index, coefficient) in decreasing order.
template <class Arithmetic, class Graph, class Progress>
std::vector<std::pair<std::size_t, typename Arithmetic::Value>>
lexicographic_homologous_chain(const Graph& graph, const std::vector<std::uint32_t>& infinite_cells,
                               const Record_values<typename Arithmetic::Value>& gamma0,
                               const Record_values<std::uint8_t>& relative, const Progress& progress)
{
  using Value = typename Arithmetic::Value;
  const Value zero = Arithmetic::zero();
  Augmented_union_find<Arithmetic> sets(graph.number_of_cells());
  if(!infinite_cells.empty()) {
    std::uint32_t root = sets.find(infinite_cells.front()).first;
    for(std::uint32_t c : infinite_cells) {
      const std::uint32_t r = sets.find(c).first;
      if(r != root) root = sets.link_roots(r, root, zero);
    }
  }
  const bool is_relative = !relative.values().empty();
  std::vector<std::pair<std::size_t, Value>> result;
  const auto& records = graph.records();
  const std::size_t m = records.size();
  constexpr std::size_t ahead = 16;
  for(std::size_t t = 0; t < m; ++t) {
    if((t & 0xfffff) == 0 && !progress(double(t) / double(m)))
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
    if(t + ahead < m) {
      const auto& next = records[m - 1 - t - ahead];
      sets.prefetch(Graph::owner_position(next));
      sets.prefetch(Graph::other_position(next));
    }
    const std::size_t index = m - 1 - t;
    const auto& r = records[index];
    if(is_relative && relative.contains(r.owner)) continue; // a triangle of B: no dual edge
    const auto [r1, g1] = sets.find(Graph::owner_position(r));
    const auto [r2, g2] = sets.find(Graph::other_position(r));
    // alpha = Gamma0(e) + g2 - g1
    const Value alpha = Arithmetic::add(Arithmetic::add(gamma0.get(r.owner, zero), g2), Arithmetic::negate(g1));
    if(r1 == r2) {
      if(alpha != zero) result.emplace_back(index, alpha);
    } else {
      sets.link_roots(r1, r2, alpha);
    }
  }
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HOMOLOGOUS_CHAIN_3_H

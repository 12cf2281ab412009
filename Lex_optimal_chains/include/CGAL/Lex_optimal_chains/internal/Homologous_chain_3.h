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

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/internal/Augmented_union_find.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Largest_facets_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>

#include <algorithm>
#include <cstdint>
#include <memory>
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

// Puts the infinite cells in one set with zero values (they all stand for the infinite
// vertex); they must be roots.
template <class Arithmetic>
void unite_infinite_cells(Augmented_union_find<Arithmetic>& sets, const std::vector<std::uint32_t>& infinite_cells)
{
  if(infinite_cells.empty()) return;
  std::uint32_t root = sets.find(infinite_cells.front()).first;
  for(std::uint32_t c : infinite_cells) {
    const std::uint32_t r = sets.find(c).first;
    if(r != root) root = sets.link_roots(r, root, Arithmetic::zero());
  }
}

// The disjoint sets of Algorithm 10 for the cells [0, n), the infinite cells already in one
// set.
template <class Arithmetic>
Augmented_union_find<Arithmetic> sets_with_infinite_node(std::size_t n, const std::vector<std::uint32_t>& infinite_cells)
{
  Augmented_union_find<Arithmetic> sets(n);
  unite_infinite_cells(sets, infinite_cells);
  return sets;
}

// The intersection product alpha = Gamma0(e) + g2 - g1 of the dual edge e from the cell of
// value g1 to the cell of value g2 (values relative to their common root).
template <class Arithmetic>
typename Arithmetic::Value intersection_product(typename Arithmetic::Value gamma0, typename Arithmetic::Value g1,
                                                typename Arithmetic::Value g2)
{
  return Arithmetic::add(Arithmetic::add(gamma0, g2), Arithmetic::negate(g1));
}

// The coefficient of a triangle of a chain returned by `lexicographic_homologous_chain()`.
template <class Arithmetic>
typename Arithmetic::Value chain_coefficient(const Dual_edge_record& entry)
{
  return typename Arithmetic::Value(std::int64_t(entry.key));
}

// Algorithm 10 on the sorted records of `graph`, from the disjoint sets `sets` (the cells
// alone, or already linked along edges of the maximum spanning forest: see
// `Contracted_homologous_graph_3`). `gamma0` holds Gamma0 on records (in their orientation);
// the records in `relative` (the triangles of B) are not edges of the dual graph. Returns the
// optimal chain in decreasing order, each triangle as a record whose `owner` is its code
// (owner position << 2 | facet index) and whose `key` holds its coefficient
// (`chain_coefficient()`). The chain is written over the records of `graph`, which keeps
// none: the entry of rank w over the record of rank w from the end, which the pass has read
// already (after a contraction, most records are in the chain, and a separate array would
// take as much fresh memory again, at the peak of memory).
template <class Arithmetic, class Graph, class Progress>
Dual_edge_records lexicographic_homologous_chain(Graph& graph, Augmented_union_find<Arithmetic>& sets,
                                                             const Record_values<typename Arithmetic::Value>& gamma0,
                                                             const Record_values<std::uint8_t>& relative,
                                                             const Progress& progress)
{
  using Value = typename Arithmetic::Value;
  const Value zero = Arithmetic::zero();
  const bool is_relative = !relative.values().empty();
  Dual_edge_records records = graph.release_records();
  const std::size_t m = records.size();
  std::size_t chain_size = 0;
  constexpr std::size_t ahead = 16;
  for(std::size_t t = 0; t < m; ++t) {
    if((t & 0xfffff) == 0 && !progress(double(t) / double(m)))
      throw Cancelled();
    if(t + ahead < m) {
      const auto& next = records[m - 1 - t - ahead];
      sets.prefetch(Graph::owner_position(next));
      sets.prefetch(Graph::other_position(next));
    }
    const Dual_edge_record r = records[m - 1 - t];
    if(is_relative && relative.contains(r.owner)) continue; // a triangle of B: no dual edge
    const auto [r1, g1] = sets.find(Graph::owner_position(r));
    const auto [r2, g2] = sets.find(Graph::other_position(r));
    const Value alpha = intersection_product<Arithmetic>(gamma0.get(r.owner, zero), g1, g2);
    if(r1 == r2) {
      if(alpha != zero) { // chain_size <= t: that record was read
        Dual_edge_record& entry = records[m - 1 - chain_size++];
        entry.owner = r.owner;
        entry.other = 0;
        entry.key = std::uint64_t(std::int64_t(alpha));
      }
    } else {
      sets.link_roots(r1, r2, alpha);
    }
  }
  // the entries, from the end backwards, moved to the front in decreasing order
  records.erase(records.begin(), records.begin() + std::ptrdiff_t(m - chain_size));
  std::reverse(records.begin(), records.end());
  return records;
}

// The dual graph of Algorithm 10 after the contraction of internal/Largest_facets_3.h.
//
// In the decreasing order, the first dual edge of a finite cell is its largest facet that is
// not in B, and the cell is alone when it is met: Algorithm 10 always links it there. Every
// cell without a triangle of B is therefore linked in advance to the cell across its largest
// facet, with the same intersection product formula. The values of the links depend on the
// order in which the links are made, but the values of the paths between two cells of a set
// do not: they are sums along the maximum spanning forest, which the contraction does not
// change (internal/Largest_facets_3.h). So Gamma0(e) + g2 - g1 is the same for every later
// edge, and only two kinds of facets need to be sorted and processed: the facets between
// different sets (Algorithm 10 may link them), and the facets within a set whose
// intersection product is not zero (they are in the result, in their place in the order).
// The links of the contraction themselves have a zero product.
template <class Arithmetic, class Triangulation>
class Contracted_homologous_graph_3
{
public:
  using Cell = typename Triangulation::Cell;
  using Graph = Sorted_dual_graph_3<Triangulation>;
  using Value = typename Arithmetic::Value;

  template <class Progress>
  Contracted_homologous_graph_3(const Triangulation& dt, const Handle_index_map<Cell>& cells,
                                const std::vector<std::uint32_t>& infinite_cells, const Record_values<Value>& gamma0,
                                const Record_values<std::uint8_t>& relative, const Progress& progress,
                                unsigned threads = 1)
    : sets_(cells.size())
  {
    const Value zero = Arithmetic::zero();
    const std::size_t n = cells.size();
    auto half = [&](double from) { return [&progress, from](double x) { return progress(from + 0.5 * x); }; };
    {
      std::vector<bool> terminal(n, false); // the cells with a triangle of B are not contracted
      for(const auto& entry : relative.values()) {
        const std::uint32_t owner = entry.first >> 2;
        terminal[owner] = true;
        terminal[cells.index(&*cells.element(owner)->neighbor(int(entry.first & 3)))] = true;
      }
      // The cell across the largest facet of each cell is written straight into the sets as
      // its parent (no array of its own, and no pass to copy it). The contractions are the edges of a forest (the only cycles are the pairs of
      // cells across the same facet, whose cell of higher position is taken as the root), and
      // each link gets the value that Algorithm 10 gives to the link of two single cells:
      // Gamma0 of the record from the owner to the other cell, negated from the other cell to
      // the owner.
      exact_comparisons_ = for_each_cell_across_largest_facet(
        dt, cells, terminal, [this](std::uint32_t c, std::uint32_t d) { if(d != c) sets_.set_parent(c, d); },
        half(0.0), threads);
      sets_.set_forest_of_parents([&](std::uint32_t c, std::uint32_t d) {
        if(!gamma0.may_contain(c) && !gamma0.may_contain(d)) return zero; // no record of Gamma0 is theirs
        const std::pair<std::uint32_t, int> facet = Graph::facet_between(dt, cells, c, d);
        const Value v = gamma0.get((facet.first << 2) | std::uint32_t(facet.second), zero);
        return facet.first == c ? v : Arithmetic::negate(v);
      });
    }
    unite_infinite_cells(sets_, infinite_cells);
    sets_.flatten(); // the filter below then reads one node per cell
    const bool is_relative = !relative.values().empty();
    graph_.reset(new Graph(dt, cells, half(0.5), [&](std::uint32_t owner, int j, std::uint32_t other) {
      const std::uint32_t code = (owner << 2) | std::uint32_t(j);
      if(is_relative && relative.contains(code)) return false; // not an edge
      const auto [r1, g1] = sets_.find_in_flat(owner);
      const auto [r2, g2] = sets_.find_in_flat(other);
      return r1 != r2 || intersection_product<Arithmetic>(gamma0.get(code, zero), g1, g2) != zero;
    }, threads));
  }

  // the sorted facets that Algorithm 10 must process
  const Graph& graph() const { return *graph_; }
  Graph& graph() { return *graph_; }
  // the disjoint sets after the contraction, for `lexicographic_homologous_chain()`
  Augmented_union_find<Arithmetic>& sets() { return sets_; }
  void release_sets() { sets_ = Augmented_union_find<Arithmetic>(); }
  void release_graph() { graph_.reset(); }
  // comparisons of the contraction that the double evaluations could not decide
  std::size_t number_of_exact_comparisons() const { return exact_comparisons_; }

private:
  Augmented_union_find<Arithmetic> sets_;
  std::unique_ptr<Graph> graph_;
  std::size_t exact_comparisons_ = 0;
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_HOMOLOGOUS_CHAIN_3_H

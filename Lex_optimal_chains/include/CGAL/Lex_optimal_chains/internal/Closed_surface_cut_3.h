// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H

// Algorithm 8 on the sorted dual graph of a 3D Delaunay triangulation completed to S^3,
// and the automatic choice of an interior cell.

#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/Lexicographic_min_cut.h>
#include <CGAL/Lex_optimal_chains/internal/Prefetch.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

inline double key_value(std::uint64_t key)
{
  key &= ~std::uint64_t(1);
  double d;
  std::memcpy(&d, &key, sizeof d);
  return d;
}

// Result of the automatic interior choice.
struct Automatic_interior
{
  std::uint32_t cell = 0;   // position of the chosen cell
  double persistence = 0;   // R_B^2 at birth / R_B^2 at death of its component
};

// The interior of a closed sampled surface is the most persistent void of the filtration
// of the complex by the triangle order: process the facets in decreasing order and unite
// the cells on both sides (a plain Kruskal on the dual graph, infinite cells merged). A
// component is born at its first (largest) facet and dies when it joins an older one
// (elder rule); the infinite component is the oldest. The cell through which the most
// persistent finite component was born, measured by the ratio of R_B^2 at birth and at
// death, is the interior. Exact ties are resolved by the order itself (the first born wins).
// `spanning_tree` receives the records that united two components, in decreasing order: the
// maximum spanning tree of the dual graph with the sinks contracted.
template <class Graph>
Automatic_interior most_persistent_void(const Graph& graph, const std::vector<std::uint32_t>& sinks,
                                        std::vector<std::uint32_t>& spanning_tree)
{
  const auto& records = graph.records();
  const std::size_t n = graph.number_of_cells();
  constexpr std::uint32_t unborn = std::numeric_limits<std::uint32_t>::max();
  Union_find sets(n);
  // per root: scan index of the record at its birth; the component holds (at least) one of
  // the two cells of that record, which represents it
  std::vector<std::uint32_t> birth(n, unborn);
  std::uint32_t sink_root = sinks.front();
  for(std::uint32_t c : sinks) sink_root = sets.unite(sink_root, c);
  birth[sink_root] = 0;
  spanning_tree.clear();

  Automatic_interior best;
  bool found = false;
  const std::size_t m = records.size();
  constexpr std::size_t ahead = 16; // records whose cells are prefetched ahead
  for(std::size_t t = 0; t < m; ++t) {
    if(t + ahead < m) {
      const auto& next = records[m - 1 - t - ahead];
      sets.prefetch(Graph::owner_position(next));
      sets.prefetch(Graph::other_position(next));
      // a cell met for the first time is its own root: its birth is read too
      prefetch_address(birth.data() + Graph::owner_position(next));
      prefetch_address(birth.data() + Graph::other_position(next));
    }
    const auto& r = records[m - 1 - t];
    const std::uint32_t scan = std::uint32_t(t + 1);
    std::uint32_t a = sets.find(Graph::owner_position(r));
    std::uint32_t b = sets.find(Graph::other_position(r));
    if(birth[a] == unborn) birth[a] = scan;
    if(birth[b] == unborn) birth[b] = scan;
    if(a == b) continue;
    // the younger one dies
    const bool a_younger = birth[a] > birth[b] || (birth[a] == birth[b] && a > b);
    const std::uint32_t young = a_younger ? a : b, old = a_younger ? b : a;
    const double born = key_value(records[m - birth[young]].key);
    const double dies = key_value(r.key);
    const double persistence = dies > 0 ? born / dies : std::numeric_limits<double>::infinity();
    if(!found || persistence > best.persistence) {
      const auto& born_with = records[m - birth[young]];
      best.cell = sets.find(Graph::owner_position(born_with)) == young ? Graph::owner_position(born_with)
                                                                       : Graph::other_position(born_with);
      best.persistence = persistence;
      found = true;
    }
    const std::uint32_t old_birth = birth[old];
    birth[sets.link_roots(a, b)] = old_birth;
    spanning_tree.push_back(std::uint32_t(m - 1 - t));
  }
  if(!found)
    throw Input_error(Input_error_code::NO_INTERIOR_FOUND,
                      "no finite cell can be taken as interior; give an interior point");
  return best;
}

// Runs Algorithm 8 from the interior cells to the infinite cells plus the exterior cells.
// Returns the cut records in decreasing order and fills `inside` (per cell position).
template <class Graph, class Progress>
std::vector<Dual_edge_record> lexicographic_closed_cut(const Graph& graph,
                                                       const std::vector<std::uint32_t>& sources,
                                                       const std::vector<std::uint32_t>& sinks,
                                                       std::vector<bool>& inside,
                                                       const Progress& progress)
{
  Lexicographic_min_cut cut(graph.number_of_cells(), sources, sinks);
  std::vector<Dual_edge_record> result;
  const auto& records = graph.records();
  const std::size_t m = records.size();
  for(std::size_t t = 0; t < m; ++t) {
    if((t & 0xfffff) == 0 && !progress(double(t) / double(m)))
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
    if(t + 16 < m) {
      const auto& next = records[m - 1 - t - 16];
      cut.prefetch(Graph::owner_position(next), Graph::other_position(next));
    }
    const auto& r = records[m - 1 - t];
    if(cut.process(Graph::owner_position(r), Graph::other_position(r))) result.push_back(r);
  }
  inside.assign(graph.number_of_cells(), false);
  for(std::uint32_t c = 0; c < graph.number_of_cells(); ++c)
    inside[c] = cut.is_on_source_side(c);
  return result;
}

// The same result as `lexicographic_closed_cut()` from the maximum spanning tree of the dual
// graph (sinks contracted, edges in decreasing order) and one source cell: Algorithm 8 only
// cuts, among the tree edges, the smallest one on the tree path from the source to the sinks,
// and its final source component is the source's side of the tree without that edge (the
// forest it builds is the tree minus that edge). So Algorithm 8 run on the tree edges alone
// gives the inside cells, and the cut is every record between an inside and an outside cell.
template <class Graph, class Progress>
std::vector<Dual_edge_record> lexicographic_closed_cut_from_tree(const Graph& graph,
                                                                 const std::vector<std::uint32_t>& spanning_tree,
                                                                 std::uint32_t source,
                                                                 const std::vector<std::uint32_t>& sinks,
                                                                 std::vector<bool>& inside,
                                                                 const Progress& progress)
{
  const auto& records = graph.records();
  Lexicographic_min_cut cut(graph.number_of_cells(), std::vector<std::uint32_t>{source}, sinks);
  for(std::size_t t = 0; t < spanning_tree.size(); ++t) {
    if((t & 0xfffff) == 0 && !progress(0.5 * double(t) / double(spanning_tree.size())))
      throw Input_error(Input_error_code::CANCELLED, "cancelled by the callback");
    if(t + 16 < spanning_tree.size()) {
      const auto& next = records[spanning_tree[t + 16]];
      cut.prefetch(Graph::owner_position(next), Graph::other_position(next));
    }
    const auto& r = records[spanning_tree[t]];
    cut.process(Graph::owner_position(r), Graph::other_position(r));
  }
  inside.assign(graph.number_of_cells(), false);
  for(std::uint32_t c = 0; c < graph.number_of_cells(); ++c)
    inside[c] = cut.is_on_source_side(c);
  std::vector<Dual_edge_record> result;
  for(std::size_t t = records.size(); t-- > 0;) {
    const auto& r = records[t];
    if(inside[Graph::owner_position(r)] != inside[Graph::other_position(r)]) result.push_back(r);
  }
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H

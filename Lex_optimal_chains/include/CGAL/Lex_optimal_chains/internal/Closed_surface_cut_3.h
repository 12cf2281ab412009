// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H

// Algorithm 8 on the dual graph of a 3D Delaunay triangulation completed to S^3, and the
// automatic choice of an interior cell, after the contraction of every cell with the cell
// across its largest facet.
//
// Algorithm 8 processes the facets in decreasing order with disjoint sets: a facet is cut
// when it joins the component of the sources to that of the sinks, its cells are united
// otherwise. The largest facet of a cell that is neither a source nor a sink is the first
// facet of that cell to be processed: the cell is alone, so the facet unites it with its
// neighbor. Uniting all these pairs beforehand changes no decision on the other facets: a
// path of such unions between two cells that are already connected to something would need,
// for its k inner cells, k + 1 largest facets, and each cell has one. So the contraction
// (internal/Largest_facets_3.h) is done first, and only the facets between different
// components are sorted and processed. On points sampled from a surface this leaves 18% of
// the facets, and the contraction gives nearly all of the spanning tree.

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/Input_error.h>
#include <CGAL/Lex_optimal_chains/internal/Dense_numbers.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>
#include <CGAL/Lex_optimal_chains/internal/Largest_facets_3.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
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
  double runner_up_persistence = 1; // the largest ratio among the other deaths (1: none above 1)
};

// The dual graph after the contraction: the cells (by position in the cell container) with
// the terminals of each kind merged and every other finite cell united with the cell across
// its largest facet, and the sorted facets between the components.
template <class Triangulation>
class Contracted_dual_graph_3
{
public:
  using Cell = typename Triangulation::Cell;
  using Graph = Sorted_dual_graph_3<Triangulation>;
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  // `sources` may be empty (the interior is then chosen by `most_persistent_void()`).
  template <class Progress>
  Contracted_dual_graph_3(const Triangulation& dt, const Handle_index_map<Cell>& cells,
                          const std::vector<std::uint32_t>& sources, const std::vector<std::uint32_t>& sinks,
                          const Progress& progress, unsigned threads = 1)
    : dt_(dt), cells_(cells), sets_(cells.size()), terminal_(cells.size(), false)
  {
    for(std::uint32_t s : sources) terminal_[s] = true;
    for(std::uint32_t s : sinks) terminal_[s] = true;
    auto half = [&](double from) { return [&progress, from](double x) { return progress(from + 0.5 * x); }; };
    // The cell across the largest facet of each cell is written straight into the sets as its
    // parent: these parents form a forest but for the pairs of cells across the same facet,
    // whose cell of higher position is taken as the root. No array of them is kept (4 bytes
    // per cell): the few that are needed later are found again (`across()`).
    exact_comparisons_ = for_each_cell_across_largest_facet(
      dt, cells, terminal_, [this](std::uint32_t p, std::uint32_t q) { if(p != q) sets_.set_parent(p, q); },
      half(0.0), threads);
    sets_.set_forest_of_parents();
    for(std::uint32_t s : sinks) sink_root_ = sink_root_ == none ? sets_.find(s) : sets_.unite(sink_root_, s);
    for(std::uint32_t s : sources)
      source_root_ = source_root_ == none ? sets_.find(s) : sets_.unite(source_root_, s);
    sets_.flatten(); // the filter below then reads one parent per cell
    sink_root_ = sets_.find(sink_root_);
    if(source_root_ != none) source_root_ = sets_.find(source_root_);
    graph_.reset(new Graph(dt, cells, half(0.5), [this](std::uint32_t a, int, std::uint32_t b) {
      return sets_.find_in_flat(a) != sets_.find_in_flat(b);
    }, threads));
  }

  const Triangulation& triangulation() const { return dt_; }
  const Handle_index_map<Cell>& cells() const { return cells_; }
  // the sorted facets between different components of the contraction
  const Graph& graph() const { return *graph_; }
  void release_graph() { graph_.reset(); }
  // the sorted facets, given away (the graph keeps none)
  Dual_edge_records release_records() { return graph_->release_records(); }
  std::size_t number_of_cells() const { return terminal_.size(); }
  // whether the cell at position `c` was contracted (it is neither a terminal nor infinite)
  bool is_contracted(std::uint32_t c) const
  {
    return !terminal_[c] && !cells_.element(c)->has_vertex(dt_.infinite_vertex());
  }
  // the cell across the largest facet of the cell at position `c`, or `c` itself if it was
  // not contracted (found again: a few reads and the comparisons of the contraction)
  std::uint32_t across(std::uint32_t c) const
  {
    if(!is_contracted(c)) return c;
    std::size_t exact = 0;
    const Cell& cell = *cells_.element(c);
    return cells_.index(&*cell.neighbor(internal::largest_facet(cell, exact)));
  }
  Union_find& sets() { return sets_; }
  const Union_find& sets() const { return sets_; }
  std::uint32_t sink_root() const { return sink_root_; }
  std::uint32_t source_root() const { return source_root_; }
  // comparisons of the contraction that the double evaluations could not decide
  std::size_t number_of_exact_comparisons() const { return exact_comparisons_; }

  // The facet between the contracted cell at position `c` and the cell across its largest
  // facet, as (owner position, facet index), the owner being chosen as in the records: the
  // finite cell, or the one of lower address if both are finite.
  std::pair<std::uint32_t, int> largest_facet(std::uint32_t c) const
  {
    return Graph::facet_between(dt_, cells_, c, across(c));
  }

  Triangle_coordinates_3 coordinates(std::pair<std::uint32_t, int> facet) const
  {
    return Graph::facet_coordinates(*cells_.element(facet.first), facet.second);
  }

  // R_B^2 as the key of the record of a facet gives it (for the persistence ratios)
  double key_value_of(std::pair<std::uint32_t, int> facet) const
  {
    std::uint64_t upper;
    return key_value(Graph::make_record(coordinates(facet), facet.first, facet.second, 0, upper).key);
  }

private:
  const Triangulation& dt_;
  const Handle_index_map<Cell>& cells_;
  Union_find sets_;
  std::vector<bool> terminal_; // per cell position: a source or a sink
  std::uint32_t sink_root_ = none, source_root_ = none;
  std::unique_ptr<Graph> graph_;
  std::size_t exact_comparisons_ = 0;
};

// The interior of a closed sampled surface is the most persistent void of the filtration of
// the complex by the triangle order: process the facets in decreasing order and unite the
// cells on both sides (a plain Kruskal on the dual graph, the sinks merged). A component is
// born at its first (largest) facet and dies when it joins an older one (elder rule); the
// component of the sinks is the oldest. The cell through which the most persistent component
// was born, measured by the ratio of R_B^2 at birth and at death, is the interior; among equal
// ratios, the first death in the order wins. The largest ratio of the other deaths is kept too:
// it tells whether the interior stands out from the voids of the noise.
//
// On the contracted graph (built without sources): a component of the contraction is born at
// its largest facet, the facet shared by the two cells whose largest facet it is, and the
// contractions themselves are deaths at birth (ratio 1). `components` receives the numbers of
// the components of the contraction, by their roots in `contracted.sets()`, which are left
// unchanged: 0 for the sinks', then in the order of the lower cells of their largest facets.
// The pass runs on disjoint sets over these numbers. `tree` receives the positions in
// `contracted.graph().records()` of the facets that united two components, in decreasing
// order: with the contractions, the maximum spanning tree of the dual graph.
template <class Triangulation>
Automatic_interior most_persistent_void(const Contracted_dual_graph_3<Triangulation>& contracted,
                                        Dense_numbers& components, std::vector<std::uint32_t>& tree)
{
  using Graph = Sorted_dual_graph_3<Triangulation>;
  using Facet = std::pair<std::uint32_t, int>;
  const auto& records = contracted.graph().records();
  const Union_find& labels = contracted.sets(); // flat: one read gives the root
  const std::uint32_t n = std::uint32_t(contracted.number_of_cells());

  // births of the components of the contraction, by number; the sinks' component has none.
  // The roots that were contracted are the cells of higher position of the pairs of cells
  // across the same facet, their largest.
  struct Birth { Facet facet; double value; std::uint32_t cell; };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs; // (lower cell, root)
  for(std::uint32_t c = 0; c < n; ++c)
    if(labels.find_in_flat(c) == c && contracted.is_contracted(c)) pairs.emplace_back(contracted.across(c), c);
  std::sort(pairs.begin(), pairs.end());
  std::vector<Birth> births(1);
  std::vector<std::uint32_t> roots(1, contracted.sink_root());
  for(const auto& [c, root] : pairs) {
    CGAL_assertion(c < root && contracted.across(c) == root);
    const Facet f = Graph::facet_between(contracted.triangulation(), contracted.cells(), c, root);
    roots.push_back(root);
    // the cell that the full Kruskal pass would report: the owner of the facet
    births.push_back(Birth{f, contracted.key_value_of(f), f.first});
  }
  components = Dense_numbers(roots.size());
  for(std::uint32_t r : roots) components.insert(r);
  CGAL_assertion(components.size() == roots.size()); // the sinks' component has no such pair
  constexpr std::uint32_t oldest = 0;
  // true if the component born at `a` is younger than the one born at `b` (smaller facet)
  auto younger = [&](std::uint32_t a, std::uint32_t b) {
    if(a == oldest) return false;
    if(b == oldest) return true;
    return compare_triangle_order(contracted.coordinates(births[a].facet),
                                  contracted.coordinates(births[b].facet)) == SMALLER;
  };

  Union_find sets(components.size());
  std::vector<std::uint32_t> birth_of_root(components.size()); // by root of `sets`
  std::iota(birth_of_root.begin(), birth_of_root.end(), std::uint32_t(0));
  tree.clear();
  Automatic_interior best;
  bool found = false;
  const std::size_t m = records.size();
  for(std::size_t t = 0; t < m; ++t) {
    if(t + 16 < m) {
      const auto& next = records[m - 1 - t - 16];
      labels.prefetch_parent(Graph::owner_position(next));
      labels.prefetch_parent(Graph::other_position(next));
    }
    const auto& r = records[m - 1 - t];
    const std::uint32_t a = sets.find(components[labels.find_in_flat(Graph::owner_position(r))]);
    const std::uint32_t b = sets.find(components[labels.find_in_flat(Graph::other_position(r))]);
    if(a == b) continue;
    const std::uint32_t ba = birth_of_root[a], bb = birth_of_root[b];
    const bool a_younger = younger(ba, bb);
    const std::uint32_t young_birth = a_younger ? ba : bb, old_birth = a_younger ? bb : ba;
    const double born = births[young_birth].value;
    const double dies = key_value(r.key);
    const double persistence = dies > 0 ? born / dies : std::numeric_limits<double>::infinity();
    if(!found || persistence > best.persistence) {
      if(found) best.runner_up_persistence = best.persistence;
      best.cell = births[young_birth].cell;
      best.persistence = persistence;
      found = true;
    } else if(persistence > best.runner_up_persistence) {
      best.runner_up_persistence = persistence;
    }
    birth_of_root[sets.link_roots(a, b)] = old_birth;
    tree.push_back(std::uint32_t(m - 1 - t));
  }
  if(!found || !(best.persistence > 1)) {
    // Every death has ratio 1 (or there is none): the full pass reports its first death, the
    // largest facet of all the contracted cells (a contraction, ratio 1).
    std::uint32_t first_cell = Contracted_dual_graph_3<Triangulation>::none;
    Facet first{};
    for(std::uint32_t c = 0; c < n; ++c) {
      if(!contracted.is_contracted(c)) continue;
      const Facet f = contracted.largest_facet(c);
      if(first_cell == Contracted_dual_graph_3<Triangulation>::none ||
         compare_triangle_order(contracted.coordinates(f), contracted.coordinates(first)) == LARGER) {
        first = f;
        first_cell = c;
      }
    }
    if(first_cell == Contracted_dual_graph_3<Triangulation>::none)
      throw Input_error(Input_error_code::NO_INTERIOR_FOUND,
                        "no finite cell can be taken as interior; give an interior point");
    // both cells were alone then: the younger is the one of larger position, unless the other
    // is a sink
    const std::uint32_t other = contracted.across(first_cell);
    best.cell = contracted.is_contracted(other) ? (std::max)(first_cell, other) : first_cell;
    best.persistence = 1;
    best.runner_up_persistence = 1;
    const double v = contracted.key_value_of(first);
    if(!(v > 0)) best.persistence = std::numeric_limits<double>::infinity();
  }
  return best;
}

// Algorithm 8 on the contracted graph built with sources: the cut facets in decreasing order;
// `inside` (per cell position) receives the final component of the sources.
template <class Triangulation, class Progress>
Dual_edge_records lexicographic_closed_cut(Contracted_dual_graph_3<Triangulation>& contracted,
                                                       std::vector<bool>& inside, const Progress& progress)
{
  using Graph = Sorted_dual_graph_3<Triangulation>;
  const auto& records = contracted.graph().records();
  Union_find& sets = contracted.sets();
  std::uint32_t source = contracted.source_root(), sink = contracted.sink_root();
  CGAL_precondition(source != Contracted_dual_graph_3<Triangulation>::none && source != sink);
  Dual_edge_records result;
  const std::size_t m = records.size();
  for(std::size_t t = 0; t < m; ++t) {
    if((t & 0xfffff) == 0 && !progress(double(t) / double(m)))
      throw Cancelled();
    if(t + 16 < m) {
      const auto& next = records[m - 1 - t - 16];
      sets.prefetch(Graph::owner_position(next));
      sets.prefetch(Graph::other_position(next));
    }
    const auto& r = records[m - 1 - t];
    const std::uint32_t a = sets.find(Graph::owner_position(r)), b = sets.find(Graph::other_position(r));
    if(a == b) continue;
    if((a == source && b == sink) || (a == sink && b == source)) {
      result.push_back(r);
      continue;
    }
    const std::uint32_t root = sets.link_roots(a, b);
    if(a == source || b == source) source = root;
    else if(a == sink || b == sink) sink = root;
  }
  inside.assign(sets.size(), false);
  for(std::uint32_t c = 0; c < sets.size(); ++c) inside[c] = sets.find(c) == source;
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_SURFACE_CUT_3_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_CUT_FROM_TREE_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_CUT_FROM_TREE_3_H

#include <CGAL/Lex_optimal_chains/Cancelled.h>
#include <CGAL/Lex_optimal_chains/internal/Closed_surface_cut_3.h>
#include <CGAL/Lex_optimal_chains/internal/Dense_numbers.h>
#include <CGAL/Lex_optimal_chains/internal/Sorted_dual_graph_3.h>
#include <CGAL/Lex_optimal_chains/internal/Triangle_order_3.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Algorithm 8 from a single source, given the maximum spanning tree that
// `most_persistent_void()` found (the contractions plus `tree`, edges between components of
// the contraction). Algorithm 8 then only cuts, among the tree edges, the smallest one on the
// tree path from the source to the sinks, and its final source component is the source's
// side of the tree without that edge. The cut is every facet between an inside and an
// outside cell. The steps:
//   1. the tree between components, rooted at the sinks' component (`parent_edges()`);
//   2. the path from the source to the sinks through contractions and tree edges;
//   3. its smallest edge, by the exact triangle order;
//   4. the source's side of the tree without that edge (`mark_source_side()`);
//   5. the facets between the sides (`cut_records()`).
template <class Triangulation>
class Closed_cut_from_tree_3
{
  using Graph = Sorted_dual_graph_3<Triangulation>;
  static constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();

  // An edge of the path: a contraction (named by its lower cell, the one whose largest facet
  // it is) or a tree edge between components (named by its index in `tree`).
  struct Path_edge
  {
    bool contraction;
    std::uint32_t index;
  };

public:
  // `components` numbers the components of the contraction as `most_persistent_void()` does
  // (the sinks' component is 0).
  Closed_cut_from_tree_3(Contracted_dual_graph_3<Triangulation>& contracted, const Dense_numbers& components,
                         const std::vector<std::uint32_t>& tree)
    : contracted_(contracted), components_(components), tree_(tree)
  {}

  // The cut in decreasing order; `inside` receives the source's side, by cell position.
  // Consumes the contraction: its sorted facets may be released.
  template <class Progress>
  Dual_edge_records cut(std::uint32_t source, const std::vector<std::uint32_t>& sinks,
                                    std::vector<bool>& inside, const Progress& progress)
  {
    const std::vector<std::uint32_t> parent_edge = parent_edges();
    check(progress, 0.1);
    const Path_edge smallest = smallest_edge(path_to_sinks(source, label(sinks.front()), parent_edge));
    check(progress, 0.2);
    mark_source_side(smallest, source, sinks, inside);
    check(progress, 0.6);
    return cut_records(smallest.contraction, inside);
  }

private:
  template <class Progress>
  static void check(const Progress& progress, double value)
  {
    if(!progress(value)) throw Cancelled();
  }

  // the component of a cell in one read (the contraction's sets are flat), and its number
  std::uint32_t label(std::uint32_t c) const { return contracted_.sets().find_in_flat(c); }
  std::uint32_t number(std::uint32_t c) const { return components_[label(c)]; }
  std::uint32_t across(std::uint32_t c) const { return contracted_.across(c); }
  const Dual_edge_record& tree_record(std::uint32_t e) const { return contracted_.graph().records()[tree_[e]]; }

  // By component number: the tree edge towards the root (the sinks' component, 0), found by
  // a breadth-first search over the tree edges incident to each component (counting sort).
  std::vector<std::uint32_t> parent_edges() const
  {
    const std::size_t k = components_.size();
    std::vector<std::uint32_t> first_incident(k + 1, 0), incident(2 * tree_.size());
    for(std::uint32_t e = 0; e < tree_.size(); ++e) {
      ++first_incident[number(Graph::owner_position(tree_record(e))) + 1];
      ++first_incident[number(Graph::other_position(tree_record(e))) + 1];
    }
    for(std::size_t i = 0; i < k; ++i) first_incident[i + 1] += first_incident[i];
    {
      std::vector<std::uint32_t> next(first_incident.begin(), first_incident.end() - 1);
      for(std::uint32_t e = 0; e < tree_.size(); ++e) {
        incident[next[number(Graph::owner_position(tree_record(e)))]++] = e;
        incident[next[number(Graph::other_position(tree_record(e)))]++] = e;
      }
    }
    std::vector<std::uint32_t> parent_edge(k, none);
    std::vector<std::uint32_t> queue{0};
    std::vector<bool> reached(k, false);
    reached[0] = true;
    for(std::size_t i = 0; i < queue.size(); ++i)
      for(std::uint32_t j = first_incident[queue[i]]; j < first_incident[queue[i] + 1]; ++j) {
        const std::uint32_t e = incident[j];
        const std::uint32_t a = number(Graph::owner_position(tree_record(e)));
        const std::uint32_t b = number(Graph::other_position(tree_record(e)));
        const std::uint32_t next = a == queue[i] ? b : a;
        if(reached[next]) continue;
        reached[next] = true;
        parent_edge[next] = e;
        queue.push_back(next);
      }
    return parent_edge;
  }

  // The cells from `c` up the contractions to a terminal cell, or to the two cells of the
  // component's largest facet.
  void climb(std::uint32_t c, std::vector<std::uint32_t>& chain) const
  {
    chain.clear();
    for(;;) {
      chain.push_back(c);
      const std::uint32_t d = across(c);
      if(d == c) return;
      if(across(d) == c) {
        chain.push_back(d);
        return;
      }
      c = d;
    }
  }

  // Appends the contractions on the path from `a` to `b`, two cells of one component.
  void append_path_within(std::uint32_t a, std::uint32_t b, std::vector<Path_edge>& path) const
  {
    if(a == b) return;
    std::vector<std::uint32_t> up_a, up_b;
    climb(a, up_a);
    std::unordered_map<std::uint32_t, std::uint32_t> rank;
    for(std::uint32_t i = 0; i < up_a.size(); ++i) rank.emplace(up_a[i], i);
    climb(b, up_b);
    std::size_t j = 0;
    while(rank.find(up_b[j]) == rank.end()) ++j;
    const std::uint32_t meet = rank[up_b[j]];
    // the contraction of the top pair is counted once: up_x[i] -> up_x[i+1]
    for(std::uint32_t i = 0; i < meet; ++i) path.push_back(Path_edge{true, up_a[i]});
    for(std::size_t i = 0; i < j; ++i) path.push_back(Path_edge{true, up_b[i]});
  }

  // The path from the source cell up the tree to a sink cell.
  std::vector<Path_edge> path_to_sinks(std::uint32_t source, std::uint32_t sink_label,
                                       const std::vector<std::uint32_t>& parent_edge) const
  {
    CGAL_assertion(components_[sink_label] == 0);
    std::vector<Path_edge> path;
    std::uint32_t at = source;
    for(std::uint32_t l = label(source); l != sink_label;) {
      const std::uint32_t e = parent_edge[components_[l]];
      std::uint32_t lower = Graph::owner_position(tree_record(e)), upper = Graph::other_position(tree_record(e));
      if(label(lower) != l) std::swap(lower, upper);
      append_path_within(at, lower, path);
      path.push_back(Path_edge{false, e});
      at = upper;
      l = label(upper);
    }
    std::vector<std::uint32_t> up; // in the sinks' component: up to a sink
    climb(at, up);
    for(std::size_t i = 0; i + 1 < up.size(); ++i) path.push_back(Path_edge{true, up[i]});
    CGAL_assertion(!path.empty());
    return path;
  }

  Triangle_coordinates_3 facet_of(const Path_edge& e) const
  {
    if(e.contraction) return contracted_.coordinates(contracted_.largest_facet(e.index));
    return contracted_.graph().coordinates(tree_record(e.index));
  }

  // The smallest edge of the path in the triangle order (exact comparisons).
  Path_edge smallest_edge(const std::vector<Path_edge>& path) const
  {
    Path_edge smallest = path.front();
    Triangle_coordinates_3 smallest_facet = facet_of(smallest);
    for(std::size_t i = 1; i < path.size(); ++i) {
      const Triangle_coordinates_3 f = facet_of(path[i]);
      if(compare_triangle_order(f, smallest_facet) == SMALLER) {
        smallest = path[i];
        smallest_facet = f;
      }
    }
    return smallest;
  }

  // Marks the cells on the source's side of the tree without the edge `smallest`.
  void mark_source_side(const Path_edge& smallest, std::uint32_t source, const std::vector<std::uint32_t>& sinks,
                        std::vector<bool>& inside) const
  {
    const std::size_t n = contracted_.number_of_cells(), k = components_.size();
    inside.assign(n, false);
    if(!smallest.contraction) {
      // A component of the contraction stays whole on one side: the sides are unions of
      // components, found with disjoint sets over their numbers; a cell is inside if its
      // root is.
      Union_find sides(k);
      for(std::uint32_t e = 0; e < tree_.size(); ++e)
        if(e != smallest.index)
          sides.unite(number(Graph::owner_position(tree_record(e))), number(Graph::other_position(tree_record(e))));
      const std::uint32_t inside_root = sides.find(number(source));
      for(std::uint32_t i = 0; i < k; ++i)
        if(sides.find(i) == inside_root) inside[components_.key(i)] = true;
      for(std::uint32_t c = 0; c < n; ++c) inside[c] = inside[label(c)]; // roots keep theirs
      return;
    }
    // The smallest edge splits a component: its cells are nodes of their own, joined by its
    // other contractions; every other component is a node named by its root.
    const std::uint32_t cut_a = smallest.index, cut_b = across(smallest.index);
    Union_find sides(n);
    const std::uint32_t split_label = label(cut_a);
    auto node = [&](std::uint32_t c) { return label(c) == split_label ? c : label(c); };
    for(std::uint32_t c = 0; c < n; ++c) {
      if(label(c) != split_label) continue;
      const std::uint32_t d = across(c);
      if(d == c || (c == cut_a && d == cut_b) || (c == cut_b && d == cut_a)) continue;
      sides.unite(c, d);
    }
    std::uint32_t sink_root = sides.find(node(sinks.front()));
    for(std::uint32_t s : sinks) sink_root = sides.unite(sink_root, node(s));
    for(std::uint32_t e = 0; e < tree_.size(); ++e)
      sides.unite(node(Graph::owner_position(tree_record(e))), node(Graph::other_position(tree_record(e))));
    const std::uint32_t inside_root = sides.find(node(source));
    for(std::uint32_t c = 0; c < n; ++c) inside[c] = sides.find(node(c)) == inside_root;
  }

  // The facets between inside and outside cells, in decreasing order. When the smallest edge
  // joins two components of the contraction, the inside is a union of components and every
  // facet of the cut is among the sorted facets; otherwise the facets between inside and
  // outside cells are sorted anew. The cut is about as large as the sorted facets, so it is
  // filtered out of them in place rather than copied (peak memory).
  Dual_edge_records cut_records(bool component_split, const std::vector<bool>& inside)
  {
    Dual_edge_records result;
    if(component_split) {
      contracted_.release_graph();
      result = Graph(contracted_.triangulation(), contracted_.cells(), [](double) { return true; },
                     [&inside](std::uint32_t a, int, std::uint32_t b) { return inside[a] != inside[b]; })
                 .release_records();
    } else {
      result = contracted_.release_records();
    }
    result.erase(std::remove_if(result.begin(), result.end(),
                                [&inside](const Dual_edge_record& r) {
                                  return inside[Graph::owner_position(r)] == inside[Graph::other_position(r)];
                                }),
                 result.end());
    std::reverse(result.begin(), result.end());
    return result;
  }

  Contracted_dual_graph_3<Triangulation>& contracted_;
  const Dense_numbers& components_;
  const std::vector<std::uint32_t>& tree_;
};

// Algorithm 8 from the single source `source` and the spanning tree of
// `most_persistent_void()` (see Closed_cut_from_tree_3).
template <class Triangulation, class Progress>
Dual_edge_records lexicographic_closed_cut_from_tree(Contracted_dual_graph_3<Triangulation>& contracted,
                                                                 const Dense_numbers& components,
                                                                 const std::vector<std::uint32_t>& tree,
                                                                 std::uint32_t source,
                                                                 const std::vector<std::uint32_t>& sinks,
                                                                 std::vector<bool>& inside, const Progress& progress)
{
  return Closed_cut_from_tree_3<Triangulation>(contracted, components, tree).cut(source, sinks, inside, progress);
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CLOSED_CUT_FROM_TREE_3_H

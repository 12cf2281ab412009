// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_SUBCOMPLEX_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_SUBCOMPLEX_3_H

// The subcomplex B of a Delaunay triangulation around a set S of feature vertices (thesis
// section 4.8.3): the simplices of dimension at most 2 inside the epsilon-offset of S, taken
// here as the simplices whose vertices are within epsilon of S and whose edges are at most
// 2 epsilon long (so that a simplex with all its vertices in the offset does not bridge two
// distant parts of it). And the optimal 1-cycles of B whose classes form a basis of H1(B):
// the critical basis of Z^min_1(B) (critical_basis() of minimal_chains.h: the sparse reduction
// of the boundaries of B's triangles, then only the beta essential cycles made minimal, each in
// O(p) for p simplices; O(p^3) at worst, as in the thesis), with B's edges in the package's
// order on edges.

#include <CGAL/Lex_optimal_chains/Chain_fields.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>
#include <CGAL/Lex_optimal_chains/internal/Handle_index_map.h>

#include <CGAL/Search_traits_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The order of the package on edges (Weighted_simplex_order with zero weights): by length,
// then by the coordinates of their sorted vertices; the lengths compared exactly by Epick's
// filtered predicate on the double coordinates (whatever the traits of the points), with no
// cache of exact values.
template <class Point>
struct Edge_length_order
{
  const std::vector<Point>* points;

  bool operator()(const Simplicial_complex::Simplex& a, const Simplicial_complex::Simplex& b) const
  {
    const std::vector<Point>& p = *points;
    using Epick = Exact_predicates_inexact_constructions_kernel;
    auto at = [&](std::uint32_t v) { return Epick::Point_3(p[v].x(), p[v].y(), p[v].z()); };
    const Comparison_result c = Epick().compare_distance_3_object()(at(a[0]), at(a[1]), at(b[0]), at(b[1]));
    if(c != EQUAL) return c == SMALLER;
    std::array<Point, 2> x{p[a[0]], p[a[1]]}, y{p[b[0]], p[b[1]]};
    if(y[1] < y[0]) std::swap(y[0], y[1]);
    if(x[1] < x[0]) std::swap(x[0], x[1]);
    return x < y;
  }
};

template <class DT>
struct Feature_subcomplex_3
{
  using Vertex_handle = typename DT::Vertex_handle;
  using Point = typename DT::Point;

  std::vector<Vertex_handle> vertices;            // vertex i of `complex`
  std::vector<Point> points;                      // their points
  Simplicial_complex complex;                     // B, on its own vertices
  std::vector<typename DT::Facet> facets;         // the triangles of B, as facets of the triangulation
  std::size_t number_of_edges = 0;

  // B around the vertices `features` of `dt` (finite), for the offset `epsilon`
  Feature_subcomplex_3(const DT& dt, const std::vector<Vertex_handle>& features, double epsilon)
  {
    using Kernel = typename DT::Geom_traits;
    using Tree_traits = Search_traits_3<Kernel>;
    using Search = Orthogonal_k_neighbor_search<Tree_traits>;
    constexpr std::uint32_t none = std::uint32_t(-1);
    std::vector<Point> feature_points;
    for(Vertex_handle v : features) feature_points.push_back(v->point());
    typename Search::Tree tree(feature_points.begin(), feature_points.end());
    const Handle_index_map<typename DT::Vertex> all(dt.tds().vertices().begin(), dt.tds().vertices().end());
    std::vector<std::uint32_t> index(all.size(), none); // in B, by index in `all`
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      Search search(tree, v->point(), 1);
      if(search.begin() == search.end() || search.begin()->second > epsilon * epsilon) continue;
      index[all.index(&*v)] = std::uint32_t(vertices.size());
      vertices.push_back(v);
      points.push_back(v->point());
    }
    complex = Simplicial_complex(std::uint32_t(vertices.size()));
    const double longest = 4 * epsilon * epsilon; // squared
    auto in_b = [&](Vertex_handle a, Vertex_handle b) {
      return index[all.index(&*a)] != none && index[all.index(&*b)] != none &&
             squared_distance(a->point(), b->point()) <= longest;
    };
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const Vertex_handle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
      if(!in_b(a, b)) continue;
      const std::uint32_t i = index[all.index(&*a)], j = index[all.index(&*b)];
      complex.add_simplex({(std::min)(i, j), (std::max)(i, j)});
      ++number_of_edges;
    }
    for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      std::array<Vertex_handle, 3> t;
      for(int k = 0; k < 3; ++k) t[k] = f->first->vertex((f->second + 1 + k) & 3);
      if(!in_b(t[0], t[1]) || !in_b(t[1], t[2]) || !in_b(t[0], t[2])) continue;
      std::array<std::uint32_t, 3> s{index[all.index(&*t[0])], index[all.index(&*t[1])], index[all.index(&*t[2])]};
      std::sort(s.begin(), s.end());
      complex.add_simplex({s[0], s[1], s[2]});
      facets.push_back(*f);
    }
  }

  // the edges of B in the package's order
  std::vector<std::uint32_t> sorted_edges() const { return sort_simplices(complex, 1, Edge_length_order<Point>{&points}); }

  // The critical basis of Z^min_1(B) over Z2, each cycle as its edges (pairs of vertices of
  // the triangulation); their classes form a basis of H1(B).
  std::vector<std::vector<std::pair<Vertex_handle, Vertex_handle>>> optimal_cycles() const
  {
    std::vector<std::vector<std::pair<Vertex_handle, Vertex_handle>>> cycles;
    if(complex.number_of_simplices(1) == 0) return cycles;
    for(const Chain<Z2_field>& cycle : critical_basis<Z2_field>(complex, 1, sorted_edges())) {
      std::vector<std::pair<Vertex_handle, Vertex_handle>> c;
      for(const auto& e : cycle) {
        const auto& s = complex.simplex(1, e.first);
        c.emplace_back(vertices[s[0]], vertices[s[1]]);
      }
      cycles.push_back(std::move(c));
    }
    return cycles;
  }
};

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_SUBCOMPLEX_3_H

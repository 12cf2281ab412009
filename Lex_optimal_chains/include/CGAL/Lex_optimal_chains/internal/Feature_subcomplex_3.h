// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_SUBCOMPLEX_3_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_FEATURE_SUBCOMPLEX_3_H

// The subcomplex B of a Delaunay triangulation around a set S of feature vertices (thesis
// section 4.8.3): the simplices of dimension at most 2 inside the epsilon-offset of S, taken
// here as the simplices whose vertices are within epsilon of S and whose edges are at most
// 2 epsilon long (so that a simplex with all its vertices in the offset does not bridge two
// distant parts of it). And the optimal 1-cycles of B whose classes form a basis of H1(B):
// the critical basis of Z^min_1(B) (minimal_chains.h, the dense reduction of B: O(p^3) for p
// simplices, as in the thesis), with its edges ordered by the package's simplex order.

#include <CGAL/Lex_optimal_chains/Chain_fields.h>
#include <CGAL/Lex_optimal_chains/Simplex_orders.h>
#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>
#include <CGAL/Lex_optimal_chains/minimal_chains.h>

#include <CGAL/Search_traits_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

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
    std::vector<Point> feature_points;
    for(Vertex_handle v : features) feature_points.push_back(v->point());
    typename Search::Tree tree(feature_points.begin(), feature_points.end());
    std::map<Vertex_handle, std::uint32_t> index;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      Search search(tree, v->point(), 1);
      if(search.begin() == search.end() || search.begin()->second > epsilon * epsilon) continue;
      index.emplace(v, std::uint32_t(vertices.size()));
      vertices.push_back(v);
      points.push_back(v->point());
    }
    complex = Simplicial_complex(std::uint32_t(vertices.size()));
    const double longest = 4 * epsilon * epsilon; // squared
    auto in_b = [&](Vertex_handle a, Vertex_handle b) {
      return index.count(a) != 0 && index.count(b) != 0 && squared_distance(a->point(), b->point()) <= longest;
    };
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const Vertex_handle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
      if(!in_b(a, b)) continue;
      complex.add_simplex({std::min(index[a], index[b]), std::max(index[a], index[b])});
      ++number_of_edges;
    }
    for(auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      std::array<Vertex_handle, 3> t;
      for(int k = 0; k < 3; ++k) t[k] = f->first->vertex((f->second + 1 + k) & 3);
      if(!in_b(t[0], t[1]) || !in_b(t[1], t[2]) || !in_b(t[0], t[2])) continue;
      std::array<std::uint32_t, 3> s{index[t[0]], index[t[1]], index[t[2]]};
      std::sort(s.begin(), s.end());
      complex.add_simplex({s[0], s[1], s[2]});
      facets.push_back(*f);
    }
  }

  // The critical basis of Z^min_1(B) over Z2, each cycle as its edges (pairs of vertices of
  // the triangulation); their classes form a basis of H1(B).
  std::vector<std::vector<std::pair<Vertex_handle, Vertex_handle>>> optimal_cycles() const
  {
    std::vector<std::vector<std::pair<Vertex_handle, Vertex_handle>>> cycles;
    if(complex.number_of_simplices(1) == 0) return cycles;
    const std::vector<double> weights(points.size(), 0.);
    const Weighted_simplex_order<Point> order(points, weights);
    const std::vector<std::uint32_t> edges = sort_simplices(complex, 1, order);
    for(const Chain<Z2_field>& cycle : critical_basis<Z2_field>(complex, 1, edges)) {
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

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_TRIANGULATION_COMPLEX_H
#define CGAL_LEX_OPTIMAL_CHAINS_TRIANGULATION_COMPLEX_H

#include <CGAL/license/Lex_optimal_chains.h>

#include <CGAL/Lex_optimal_chains/Simplicial_complex.h>

#include <map>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {

/*!
\ingroup PkgLexOptimalChainsRef
A `Simplicial_complex` made from a CGAL triangulation, and the triangulation vertex of each of
its vertices.
*/
template <class Triangulation>
struct Triangulation_complex
{
  Simplicial_complex complex;                                  ///< the finite simplices
  std::vector<typename Triangulation::Vertex_handle> vertices; ///< vertex `i` of the complex
};

/*!
\ingroup PkgLexOptimalChainsRef
The simplicial complex of the finite simplices of a 2D triangulation
(`Delaunay_triangulation_2`, `Regular_triangulation_2`, ...): its finite faces, or its finite
edges and vertices in dimension below 2. Vertices are numbered in the order of the finite
vertex iterator.
*/
template <class Triangulation_2>
Triangulation_complex<Triangulation_2> triangulation_complex_2(const Triangulation_2& tr)
{
  Triangulation_complex<Triangulation_2> result;
  std::map<typename Triangulation_2::Vertex_handle, std::uint32_t> index;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    index[v] = std::uint32_t(result.vertices.size());
    result.vertices.push_back(v);
  }
  result.complex = Simplicial_complex(std::uint32_t(result.vertices.size()));
  if(tr.dimension() == 2) {
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
      result.complex.add_simplex({index[f->vertex(0)], index[f->vertex(1)], index[f->vertex(2)]});
  } else if(tr.dimension() == 1) {
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e)
      result.complex.add_simplex({index[e->first->vertex(tr.cw(e->second))], index[e->first->vertex(tr.ccw(e->second))]});
  }
  return result;
}

/*!
\ingroup PkgLexOptimalChainsRef
The simplicial complex of the finite simplices of a 3D triangulation
(`Delaunay_triangulation_3`, `Regular_triangulation_3`, ...): its finite cells, or its
finite facets, edges and vertices in dimension below 3. Vertices are numbered in the order of
the finite vertex iterator.
*/
template <class Triangulation_3>
Triangulation_complex<Triangulation_3> triangulation_complex_3(const Triangulation_3& tr)
{
  Triangulation_complex<Triangulation_3> result;
  std::map<typename Triangulation_3::Vertex_handle, std::uint32_t> index;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    index[v] = std::uint32_t(result.vertices.size());
    result.vertices.push_back(v);
  }
  result.complex = Simplicial_complex(std::uint32_t(result.vertices.size()));
  if(tr.dimension() == 3) {
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
      result.complex.add_simplex({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
  } else {
    for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f) {
      Simplicial_complex::Simplex s;
      for(int i = 0; i < 4; ++i)
        if(i != f->second && f->first->vertex(i) != tr.infinite_vertex()) s.push_back(index[f->first->vertex(i)]);
      if(s.size() == 3) result.complex.add_simplex(s);
    }
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e)
      result.complex.add_simplex({index[e->first->vertex(e->second)], index[e->first->vertex(e->third)]});
  }
  return result;
}

} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_TRIANGULATION_COMPLEX_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UMBRELLAS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UMBRELLAS_H

// The non-manifold vertices of a set of triangles (a triangle soup given by the vertex
// numbers of its corners), found with arrays only. The triangles at a vertex v are bucketed
// by a counting sort; each gives an edge of the link of v (the edge joining its two other
// vertices). v is manifold when its link is one path or one cycle: no link vertex of degree
// three or more (the ends of an edge of three triangles or more), and one connected
// component. A vertex has a few triangles: its link is checked in place, without sorting.

#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Whether the edges `link` (pairs of vertex numbers, a few) form one path or one cycle: every
// vertex on at most two of them, and a walk from an end (from any vertex, for a cycle) along
// unused edges uses them all. Quadratic in the number of edges, without allocation.
inline bool is_one_path_or_cycle(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& link, std::vector<char>& used)
{
  const std::size_t m = link.size();
  auto degree = [&](std::uint32_t x) {
    int d = 0;
    for(const auto& e : link) d += int(e.first == x) + int(e.second == x);
    return d;
  };
  std::uint32_t start = link[0].first;
  for(const auto& e : link)
    for(const std::uint32_t x : {e.first, e.second}) {
      const int d = degree(x);
      if(d > 2) return false;
      if(d == 1) start = x;
    }
  used.assign(m, 0);
  std::uint32_t at = start;
  for(std::size_t walked = 0;; ++walked) {
    std::size_t next = m;
    for(std::size_t i = 0; i < m && next == m; ++i)
      if(!used[i] && (link[i].first == at || link[i].second == at)) next = i;
    if(next == m) return walked == m;
    used[next] = 1;
    at = link[next].first == at ? link[next].second : link[next].first;
  }
}

// The vertex numbers (increasing) of the vertices that are not manifold in the triangles
// t = 0 .. number_of_triangles - 1, whose corners 3 t + k are at `corner_vertex(3 t + k)` in
// [0, number_of_vertices). The orientation of the triangles does not matter.
template <class CornerVertex>
std::vector<std::uint32_t> vertices_with_several_umbrellas(std::size_t number_of_vertices, std::uint32_t number_of_triangles,
                                                           const CornerVertex& corner_vertex)
{
  using Index = std::uint32_t;
  const Index nc = 3 * number_of_triangles;
  Large_vector<Index> bucket(nc); // corners by vertex
  const Large_vector<std::uint32_t> first =
    counting_sort_by_key(number_of_vertices, nc, corner_vertex, [&](Index c, Index at) { bucket[at] = c; });
  std::vector<Index> result;
  std::vector<std::pair<Index, Index>> link; // edges of the link of a vertex
  std::vector<char> used;
  for(Index v = 0; v < number_of_vertices; ++v) {
    if(first[v + 1] - first[v] < 2) continue; // no triangle, or a single one: a fan
    link.clear();
    for(Index i = first[v]; i < first[v + 1]; ++i) {
      const Index c = bucket[i], t = 3 * (c / 3), k = c % 3;
      link.emplace_back(corner_vertex(t + (k + 1) % 3), corner_vertex(t + (k + 2) % 3));
    }
    if(!is_one_path_or_cycle(link, used)) result.push_back(v);
  }
  return result;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_UMBRELLAS_H

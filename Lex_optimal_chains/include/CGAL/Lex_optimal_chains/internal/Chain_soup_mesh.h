// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_MESH_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_MESH_H

// A triangle soup (the support of a 2-chain) made a valid polygon mesh, with arrays and
// bucketing only, in time linear in the soup (PMP::orient_polygon_soup() does the same with
// associative maps):
// - an edge joins the two triangles that share it if it has exactly two; an edge of three
//   triangles or more is cut (each triangle gets its own copy);
// - over Z2 the triangles are oriented by a breadth-first traversal across joined edges; a
//   joined edge found inconsistent afterwards (a Möbius strip) is cut; over Q the given
//   orientation is kept and a joined edge whose two triangles run the same way is cut;
// - each vertex gets one copy per umbrella: per class of its corners connected through
//   joined edges.

#include <CGAL/Lex_optimal_chains/internal/Edge_groups.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

struct Chain_soup_statistics
{
  std::size_t vertex_copies = 0;       // vertices added to separate umbrellas
  std::size_t non_manifold_edges = 0;  // edges of three triangles or more
  std::size_t orientation_cuts = 0;    // joined edges cut to orient the soup
};

// `triangles` index `points`; they may be flipped (Z2). The mesh receives the result.
template <class Point, class PolygonMesh>
Chain_soup_statistics add_chain_soup(const std::vector<Point>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                                     bool oriented, PolygonMesh& mesh)
{
  using Index = std::uint32_t;
  constexpr Index none = std::numeric_limits<Index>::max();
  Chain_soup_statistics stats;
  const std::size_t f = triangles.size();
  // half-edge h = 3 t + k runs from triangles[t][k] to triangles[t][(k+1)%3]
  auto source = [&](std::size_t h) { return triangles[h / 3][h % 3]; };
  std::vector<Index> mate(3 * f, none);
  for_each_edge_group(points.size(), Index(3 * f), [&](Index c) { return triangles[c / 3][c % 3]; },
                      [&](const Index* first, const Index* last) {
                        if(last - first == 2) {
                          mate[first[0]] = first[1];
                          mate[first[1]] = first[0];
                        } else if(last - first > 2) {
                          ++stats.non_manifold_edges;
                        }
                      });

  if(!oriented) { // breadth-first orientation, triangle by triangle in their order
    std::vector<char> seen(f, 0);
    std::vector<Index> queue;
    for(std::size_t start = 0; start < f; ++start) {
      if(seen[start]) continue;
      seen[start] = 1;
      queue.assign(1, Index(start));
      for(std::size_t q = 0; q < queue.size(); ++q) {
        const Index t = queue[q];
        for(int k = 0; k < 3; ++k) {
          const Index m = mate[3 * t + k];
          if(m == none || seen[m / 3]) continue;
          seen[m / 3] = 1;
          // consistent if the mate runs the other way: flip its triangle otherwise
          if(source(m) == source(3 * t + k)) {
            auto& tri = triangles[m / 3];
            std::swap(tri[1], tri[2]);
            // the half-edges of the flipped triangle: k -> 2 - k
            Index moved[3];
            for(int c = 0; c < 3; ++c) moved[c] = mate[3 * (m / 3) + c];
            for(int c = 0; c < 3; ++c) {
              mate[3 * (m / 3) + (2 - c)] = moved[c];
              if(moved[c] != none) mate[moved[c]] = Index(3 * (m / 3) + (2 - c));
            }
          }
          queue.push_back(m / 3);
        }
      }
    }
  }
  // cut the joined edges whose triangles run the same way
  for(std::size_t h = 0; h < 3 * f; ++h) {
    const Index m = mate[h];
    if(m != none && m > h && source(m) == source(h)) {
      mate[h] = mate[m] = none;
      ++stats.orientation_cuts;
    }
  }
  // umbrellas: corner 3 t + k is at vertex triangles[t][k]; the joined half-edges h (a -> b)
  // and m (b -> a) put together the corners at a (h and next(m)) and at b (next(h) and m)
  Union_find corners(3 * f);
  auto next = [](std::size_t h) { return Index(3 * (h / 3) + (h % 3 + 1) % 3); };
  for(std::size_t h = 0; h < 3 * f; ++h) {
    const Index m = mate[h];
    if(m == none || m < h) continue;
    corners.unite(Index(h), next(m));
    corners.unite(next(h), m);
  }
  std::vector<Point> out_points;
  out_points.reserve(points.size());
  std::vector<Index> copy_of_root(3 * f, none), copies(points.size(), 0);
  std::vector<std::array<std::size_t, 3>> out_triangles(f);
  for(std::size_t c = 0; c < 3 * f; ++c) {
    const Index r = corners.find(Index(c));
    if(copy_of_root[r] == none) {
      const Index v = triangles[c / 3][c % 3];
      copy_of_root[r] = Index(out_points.size());
      out_points.push_back(points[v]);
      if(copies[v]++ > 0) ++stats.vertex_copies;
    }
    out_triangles[c / 3][c % 3] = copy_of_root[r];
  }
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(out_points, out_triangles, mesh);
  return stats;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_CHAIN_SOUP_MESH_H

// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PINCHED_UMBRELLA_TRIM_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PINCHED_UMBRELLA_TRIM_H

// The fringe of a surface whose triangles at some vertices were dropped (drop_boundary_triangles)
// made manifold. Dropping the triangles at the boundary vertices that are not input points
// can leave an input point v with several umbrellas: fans of triangles that met at v only
// through dropped triangles (a pinch; on CGAL's `poste_france.xyz`, three of them, with 1 to 11
// triangles a fan). The triangles of all umbrellas at v but one are dropped as well: the one
// kept lies in the largest edge-connected part of the surface, then has the most triangles,
// then holds the smallest triangle (the triangles are sorted by the numbers of their vertices,
// which are in the order of their points, so the choice does not depend on the input order).
// Removing a fan can pinch the vertices at its rim: rounds repeat until no vertex has two
// umbrellas. Each round removes triangles, so they end.
//
// A vertex whose triangles form one umbrella but where an edge has three triangles or more is
// not a pinch: it is left to the mesh builder, which splits it.

#include <CGAL/Lex_optimal_chains/internal/Edge_groups.h>
#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>
#include <CGAL/Lex_optimal_chains/internal/Umbrellas.h>
#include <CGAL/Lex_optimal_chains/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// The umbrellas at one vertex: its triangles `at` grouped by the connected components of the
// link (the edges opposite to the vertex); returns the group of each triangle, and the number
// of groups. A vertex has a few triangles: quadratic, without allocation beyond `group`.
inline std::size_t umbrellas_at_vertex(const std::vector<std::array<std::uint32_t, 2>>& link, std::vector<std::size_t>& group)
{
  const std::size_t m = link.size();
  group.resize(m);
  for(std::size_t i = 0; i < m; ++i) group[i] = i;
  auto root = [&](std::size_t i) {
    while(group[i] != i) i = group[i];
    return i;
  };
  for(std::size_t i = 0; i < m; ++i)
    for(std::size_t j = i + 1; j < m; ++j) {
      const bool touch = link[i][0] == link[j][0] || link[i][0] == link[j][1] || link[i][1] == link[j][0] ||
                         link[i][1] == link[j][1];
      if(touch) {
        const std::size_t a = root(i), b = root(j);
        if(a != b) group[(std::max)(a, b)] = (std::min)(a, b);
      }
    }
  std::size_t count = 0;
  for(std::size_t i = 0; i < m; ++i) {
    group[i] = root(i);
    count += std::size_t(group[i] == i);
  }
  return count;
}

// Removes from `triangles` (on points 0 .. number_of_points - 1, sorted) the umbrellas that
// pinch the surface, as said above; keeps the order of the others. Returns the number of
// triangles removed.
inline std::size_t trim_pinched_umbrellas(std::size_t number_of_points, std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  using Index = std::uint32_t;
  std::size_t removed = 0;
  std::vector<std::array<Index, 2>> link;
  std::vector<Index> at; // the triangles at a vertex
  std::vector<std::size_t> group;
  for(;;) {
    const Index f = Index(triangles.size());
    auto corner = [&](Index c) { return triangles[c / 3][c % 3]; };
    const std::vector<Index> several = vertices_with_several_umbrellas(number_of_points, f, corner);
    if(several.empty()) break;
    // the edge-connected parts of the surface, and their sizes
    Union_find part(f);
    for_each_edge_group(number_of_points, 3 * f, corner, [&](const Index* first, const Index* last) {
      if(last - first == 2) part.unite(first[0] / 3, first[1] / 3);
    });
    std::vector<Index> part_size(f, 0);
    for(Index t = 0; t < f; ++t) ++part_size[part.find(t)];
    Large_vector<Index> bucket(3 * f); // corners by vertex
    const Large_vector<Index> first =
      counting_sort_by_key(number_of_points, 3 * f, corner, [&](Index c, Index i) { bucket[i] = c; });
    std::vector<char> doomed(f, 0);
    bool pinched = false;
    for(const Index v : several) {
      link.clear();
      at.clear();
      for(Index i = first[v]; i < first[v + 1]; ++i) {
        const Index c = bucket[i], t = c / 3, k = c % 3;
        link.push_back({triangles[t][(k + 1) % 3], triangles[t][(k + 2) % 3]});
        at.push_back(t);
      }
      if(umbrellas_at_vertex(link, group) < 2) continue; // an edge of three triangles: not a pinch
      pinched = true;
      // the umbrella kept: (largest part, most triangles, smallest triangle), compared as
      // (-part, -count, triangle); `at` is increasing, so an umbrella's first triangle is its smallest
      std::size_t kept = group[0];
      auto key = [&](std::size_t g) {
        const std::size_t count = std::size_t(std::count(group.begin(), group.end(), g));
        const std::size_t first_at = std::size_t(std::find(group.begin(), group.end(), g) - group.begin());
        return std::make_tuple(-long(part_size[part.find(at[first_at])]), -long(count), at[first_at]);
      };
      for(std::size_t i = 0; i < group.size(); ++i)
        if(group[i] == i && key(i) < key(kept)) kept = i;
      for(std::size_t i = 0; i < group.size(); ++i)
        if(group[i] != kept) doomed[at[i]] = 1;
    }
    if(!pinched) break;
    std::size_t next = 0;
    for(Index t = 0; t < f; ++t)
      if(!doomed[t]) triangles[next++] = triangles[t];
    removed += f - next;
    triangles.resize(next);
  }
  return removed;
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_PINCHED_UMBRELLA_TRIM_H

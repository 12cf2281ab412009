// Copyright (c) 2026  The Lex_optimal_chains authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_EDGE_GROUPS_H
#define CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_EDGE_GROUPS_H

// The half-edges of a set of triangles grouped by the edge (pair of vertices) they lie on,
// without sorting all of them: half-edges are bucketed by their smaller vertex (a counting
// sort), and a bucket, whose size is about twice the number of larger neighbors of its
// vertex, is grouped by the larger vertex with a few passes, or sorted when it is large.
// Half-edge h = 3 t + k of triangle t runs from corner h to corner 3 t + (k + 1) % 3.

#include <CGAL/Lex_optimal_chains/internal/Radix_sort.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lex_optimal_chains {
namespace internal {

// Calls `group(first, last)` once per edge with the range of the (one or more) half-edges on
// it. `corner_vertex(c)` is the vertex index of corner `c`, in [0, number_of_vertices).
// Groups come in increasing order of their smaller vertex; within a group, half-edges come
// in increasing order. Costs O(h + v) plus the grouping of the buckets.
template <class CornerVertex, class Group>
void for_each_edge_group(std::size_t number_of_vertices, std::uint32_t number_of_half_edges,
                         const CornerVertex& corner_vertex, const Group& group)
{
  const std::uint32_t nh = number_of_half_edges;
  auto tail = [&](std::uint32_t h) { return corner_vertex(h); };
  auto head = [&](std::uint32_t h) { return corner_vertex(3 * (h / 3) + (h % 3 + 1) % 3); };
  auto smaller = [&](std::uint32_t h) { return (std::min)(tail(h), head(h)); };
  auto larger = [&](std::uint32_t h) { return (std::max)(tail(h), head(h)); };
  Large_vector<std::uint32_t> bucket(nh); // increasing in a bucket
  const Large_vector<std::uint32_t> first =
    counting_sort_by_key(number_of_vertices, nh, smaller, [&](std::uint32_t h, std::uint32_t at) { bucket[at] = h; });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted; // (larger vertex, half-edge)
  for(std::size_t v = 0; v < number_of_vertices; ++v) {
    std::uint32_t* const begin = bucket.data() + first[v];
    std::uint32_t* const end = bucket.data() + first[v + 1];
    if(end - begin > 32) {
      sorted.clear();
      for(std::uint32_t* p = begin; p < end; ++p) sorted.emplace_back(larger(*p), *p);
      std::sort(sorted.begin(), sorted.end());
      for(std::size_t i = 0; i < sorted.size(); ++i) begin[i] = sorted[i].second;
      for(std::uint32_t* p = begin; p < end;) {
        std::uint32_t* q = p + 1;
        while(q < end && larger(*q) == larger(*p)) ++q;
        group(static_cast<const std::uint32_t*>(p), static_cast<const std::uint32_t*>(q));
        p = q;
      }
      continue;
    }
    // small bucket: the half-edges on the edge of the first one are moved next to it (a
    // stable partition of the rest), then the group is reported
    for(std::uint32_t* p = begin; p < end;) {
      const std::uint32_t other = larger(*p);
      std::uint32_t* q = p + 1;
      for(std::uint32_t* r = p + 1; r < end; ++r)
        if(larger(*r) == other) std::rotate(q++, r, r + 1);
      group(static_cast<const std::uint32_t*>(p), static_cast<const std::uint32_t*>(q));
      p = q;
    }
  }
}

} // namespace internal
} // namespace Lex_optimal_chains
} // namespace CGAL

#endif // CGAL_LEX_OPTIMAL_CHAINS_INTERNAL_EDGE_GROUPS_H

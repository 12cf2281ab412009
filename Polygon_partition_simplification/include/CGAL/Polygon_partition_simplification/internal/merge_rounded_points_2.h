// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H

// The points of a partition are computed in double from their lines, and two of them must
// not coincide. Distinct exact points can round to the same coordinates: the end of a segment
// whose line passes within a rounding error of a corner of the bounding box (whose corners
// are rounded), next to that corner; or two intersections of nearly identical lines. Points
// that coincide so and are joined by an edge are merged, as the collapse of that edge: the
// merged point is on all their lines (on two sides of the box, it is the corner).

#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// `lines`, `vertices` and `edges`: those of a `Line_partition_2` (edges with source < target,
// sorted by (line, source, target)); the points merged, the collapsed edges removed, and the
// edges sorted again and made distinct.
template <class Line, class Vertex, class Edge>
void merge_points_that_round_together(const std::vector<Line>& lines, std::vector<Vertex>& vertices,
                                      std::vector<Edge>& edges)
{
  const std::size_t n = vertices.size();
  std::vector<std::array<double, 2>> position(n);
  for(std::size_t v = 0; v < n; ++v)
    position[v] = point_of_lines(
      vertices[v].lines, [&](std::size_t l) -> const Vector_3d& { return lines[l].coefficients; },
      [&](std::size_t l) { return lines[l].is_fixed; });
  // The merged points are numbered as their smallest member, in the order of the points: the
  // sets keep their smallest member as representative.
  Union_find<std::size_t> sets(n);
  bool merged = false;
  for(const Edge& e : edges)
    if(position[e.source] == position[e.target]) {
      sets.unite_at_smallest(e.source, e.target);
      merged = true;
    }
  if(!merged) return;
  std::vector<std::size_t> new_index(n, std::size_t(-1));
  std::vector<Vertex> kept;
  for(std::size_t v = 0; v < n; ++v)
    if(sets.find(v) == v) {
      new_index[v] = kept.size();
      kept.push_back(vertices[v]);
    }
  for(std::size_t v = 0; v < n; ++v)
    if(sets.find(v) != v) {
      auto& l = kept[new_index[sets.find(v)]].lines;
      l.insert(l.end(), vertices[v].lines.begin(), vertices[v].lines.end());
    }
  for(Vertex& v : kept) {
    std::sort(v.lines.begin(), v.lines.end());
    v.lines.erase(std::unique(v.lines.begin(), v.lines.end()), v.lines.end());
  }
  std::vector<Edge> remaining;
  for(Edge e : edges) {
    e.source = new_index[sets.find(e.source)];
    e.target = new_index[sets.find(e.target)];
    if(e.source == e.target) continue; // the collapsed edge
    if(e.source > e.target) std::swap(e.source, e.target);
    remaining.push_back(e);
  }
  std::sort(remaining.begin(), remaining.end(), [](const Edge& x, const Edge& y) {
    return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
  });
  remaining.erase(std::unique(remaining.begin(), remaining.end(), [](const Edge& x, const Edge& y) {
                    return std::tie(x.line, x.source, x.target) == std::tie(y.line, y.source, y.target);
                  }), remaining.end());
  vertices.swap(kept);
  edges.swap(remaining);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H

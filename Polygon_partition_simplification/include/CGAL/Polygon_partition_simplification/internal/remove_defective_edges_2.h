// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_REMOVE_DEFECTIVE_EDGES_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_REMOVE_DEFECTIVE_EDGES_2_H

// The last step of the rounding of a partition built from exact pieces (build_line_partition_2.h),
// which makes it valid whatever the rounds of merge_rounded_points_2.h left: while the partition,
// its points computed from its lines as the user gets them, has a defect (decided with exact
// predicates, partition_defect()), the shortest edge involved in the defect that is not on a
// side of the bounding rectangle is removed, then the edges left dangling, then points where two
// edges of one line meet and no other edge does (the two edges joined). Each step lowers the
// numbers of edges and points (lexicographically), so the loop ends, with a valid partition or
// with one whose defects involve sides of the rectangle only (which no input makes: the sides
// are far from every point of the segments). What is removed is what double precision cannot
// hold apart: features below the rounding tolerance that the rounds could not settle.

#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>
#include <CGAL/Polygon_partition_simplification/internal/merge_rounded_points_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// `lines`, `vertices` and `edges` as partition_defect() sees them
template <class Line, class Vertex, class Edge>
struct Rounded_partition_view
{
  const std::vector<Line>& lines;
  const std::vector<Vertex>& vertices;
  const std::vector<Edge>& edges;
  std::size_t number_of_lines() const { return lines.size(); }
  const Vector_3d& coefficients(std::size_t l) const { return lines[l].coefficients; }
  bool is_fixed(std::size_t l) const { return lines[l].is_fixed; }
  std::size_t number_of_vertices() const { return vertices.size(); }
  const std::vector<std::size_t>& vertex_lines(std::size_t v) const { return vertices[v].lines; }
  std::size_t number_of_edges() const { return edges.size(); }
  std::array<std::size_t, 3> edge(std::size_t e) const { return {{edges[e].line, edges[e].source, edges[e].target}}; }
};

// One pass of remove_dangling_and_join(); returns the number of edges removed, joins and
// repeated edges not counted.
template <class Vertex, class Edge>
std::size_t remove_dangling_and_join_once(std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  const std::size_t nv = vertices.size(), given = edges.size();
  std::vector<std::size_t> degree(nv);
  for(;;) {
    std::fill(degree.begin(), degree.end(), 0);
    for(const Edge& e : edges) { ++degree[e.source]; ++degree[e.target]; }
    const std::size_t before = edges.size();
    edges.erase(std::remove_if(edges.begin(), edges.end(),
                               [&](const Edge& e) { return degree[e.source] == 1 || degree[e.target] == 1; }),
                edges.end());
    if(edges.size() == before) break;
  }
  const std::size_t dangling = given - edges.size();
  // two edges of one line at a point of degree 2, joined: the first one is kept and goes on to
  // the other end of the second one
  std::vector<std::vector<std::size_t>> incident(nv);
  for(std::size_t i = 0; i < edges.size(); ++i) {
    incident[edges[i].source].push_back(i);
    incident[edges[i].target].push_back(i);
  }
  std::vector<bool> joined(edges.size(), false);
  for(std::size_t v = 0; v < nv; ++v) {
    if(incident[v].size() != 2) continue;
    const std::size_t i = std::min(incident[v][0], incident[v][1]), j = std::max(incident[v][0], incident[v][1]);
    if(i == j || edges[i].line != edges[j].line) continue;
    const std::size_t a = edges[i].source == v ? edges[i].target : edges[i].source;
    const std::size_t b = edges[j].source == v ? edges[j].target : edges[j].source;
    edges[i].source = std::min(a, b);
    edges[i].target = std::max(a, b);
    joined[j] = true;
    incident[v].clear();
    std::replace(incident[b].begin(), incident[b].end(), j, i);
  }
  std::vector<Edge> remaining;
  for(std::size_t i = 0; i < edges.size(); ++i)
    if(!joined[i] && edges[i].source != edges[i].target) remaining.push_back(edges[i]);
  // drop the points without edges
  std::vector<std::size_t> new_index(nv, std::size_t(-1));
  for(const Edge& e : remaining) { new_index[e.source] = 0; new_index[e.target] = 0; }
  std::vector<Vertex> kept_vertices;
  for(std::size_t v = 0; v < nv; ++v)
    if(new_index[v] == 0) { new_index[v] = kept_vertices.size(); kept_vertices.push_back(vertices[v]); }
  for(Edge& e : remaining) {
    e.source = new_index[e.source];
    e.target = new_index[e.target];
    if(e.source > e.target) std::swap(e.source, e.target);
  }
  sort_distinct_edges(remaining);
  vertices.swap(kept_vertices);
  edges.swap(remaining);
  return dangling;
}

// Removes the edges with an end where no other edge is, repeatedly, then joins the two edges at
// each point where exactly two edges of one line meet, and drops the points left without edges;
// all this again until nothing changes (a join can make an edge repeat another, whose removal
// leaves an end alone). The edges stay sorted by (line, source, target). Returns the number of
// edges removed (joins not counted: the joined edge covers both).
template <class Vertex, class Edge>
std::size_t remove_dangling_and_join(std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  std::size_t removed = 0;
  for(;;) {
    const std::size_t points = vertices.size(), edge_count = edges.size();
    removed += remove_dangling_and_join_once(vertices, edges);
    if(vertices.size() == points && edges.size() == edge_count) return removed;
  }
}

// Takes off each point the lines that have no edge (as canonical_partition() does), so that the
// points checked are computed as those of the result.
template <class Vertex, class Edge>
void drop_lines_without_edges(std::size_t number_of_lines, std::vector<Vertex>& vertices, const std::vector<Edge>& edges)
{
  std::vector<bool> used(number_of_lines, false);
  for(const Edge& e : edges) used[e.line] = true;
  for(Vertex& v : vertices)
    v.lines.erase(std::remove_if(v.lines.begin(), v.lines.end(), [&](std::size_t l) { return !used[l]; }), v.lines.end());
}

// Removes edges of `edges` (see above) until the partition of `lines`, `vertices` and `edges`
// is valid, or until only edges on fixed lines are involved in its defects (the partition is
// then returned invalid, as `defect()` says). Returns the number of edges removed, dangling ones
// included (joins not counted). `GeomTraits`: a model of
// `PolygonPartitionSimplificationTraits_2`, whose kernels decide.
template <class GeomTraits, class Line, class Vertex, class Edge>
std::size_t remove_defective_edges(const std::vector<Line>& lines, std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  using PK = typename GeomTraits::Exact_predicates_kernel;
  std::size_t removed = 0;
  std::vector<std::size_t> defective;
  for(bool first = true;; first = false) {
    defective.clear();
    drop_lines_without_edges(lines.size(), vertices, edges);
    const Rounded_partition_view<Line, Vertex, Edge> view{lines, vertices, edges};
    if(partition_defect<GeomTraits>(view, &defective, All_crossing_pairs<PK>()).empty()) return removed;
    if(first) { // dangling edges and points left on one line by the rounds, before anything else
      const std::size_t points = vertices.size(), edge_count = edges.size();
      removed += remove_dangling_and_join(vertices, edges);
      if(vertices.size() != points || edges.size() != edge_count) continue;
    }
    const std::vector<std::array<double, 2>> position = point_positions(lines, vertices);
    auto length = [&](std::size_t e) {
      const auto& p = position[edges[e].source];
      const auto& q = position[edges[e].target];
      const double l = std::hypot(q[0] - p[0], q[1] - p[1]);
      return std::isfinite(l) ? l : 0.; // an edge at a point at infinity goes first
    };
    // the shortest defective edge off the sides (on a tie, the first by its line and the lines
    // of its points, which do not depend on the order of the input); after many removals (a
    // scene far beyond what double precision holds), all of them at once
    auto before = [&](std::size_t e, std::size_t f) {
      const double le = length(e), lf = length(f);
      if(le != lf) return le < lf;
      if(edges[e].line != edges[f].line) return edges[e].line < edges[f].line;
      auto ends = [&](std::size_t x) { // the lines of its points, in order
        return std::minmax(vertices[edges[x].source].lines, vertices[edges[x].target].lines);
      };
      const auto ee = ends(e), ef = ends(f);
      return std::tie(ee.first, ee.second) < std::tie(ef.first, ef.second);
    };
    std::vector<bool> remove(edges.size(), false);
    std::size_t shortest = std::size_t(-1);
    for(std::size_t e : defective) {
      if(lines[edges[e].line].is_fixed) continue;
      if(removed >= 32) remove[e] = true;
      else if(shortest == std::size_t(-1) || before(e, shortest)) shortest = e;
    }
    if(shortest != std::size_t(-1)) remove[shortest] = true;
    const std::size_t count = std::size_t(std::count(remove.begin(), remove.end(), true));
    if(count == 0) return removed; // only sides of the rectangle are involved
    removed += count;
    std::vector<Edge> kept;
    for(std::size_t e = 0; e < edges.size(); ++e)
      if(!remove[e]) kept.push_back(edges[e]);
    edges.swap(kept);
    removed += remove_dangling_and_join(vertices, edges);
  }
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_REMOVE_DEFECTIVE_EDGES_2_H

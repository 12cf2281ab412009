// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H

// The points of a partition are computed in double from their lines, and two of them must
// not coincide. Distinct exact points can round to the same coordinates, or to coordinates in
// the wrong order: the end of a segment whose line passes within a rounding error of a corner
// of the bounding box (whose corners are rounded), next to that corner; two intersections of
// nearly identical lines; the three intersections of three nearly concurrent lines (a triangle
// far smaller than the rounding errors of the points computed from the lines). Points that come
// so close and are joined by an edge are merged, as the collapse of that edge: the merged point
// is on all their lines (on two sides of the box, it is the corner). A point that comes that
// close to an edge is put on it, and edges whose double coordinates cross are split where they
// do, as iterated snap rounding routes segments through the hot pixels of points and
// intersections.

#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Segment_grid_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The positions of the points (normalized frame), computed from their lines.
template <class Line, class Vertex>
std::vector<std::array<double, 2>> point_positions(const std::vector<Line>& lines, const std::vector<Vertex>& vertices)
{
  std::vector<std::array<double, 2>> position(vertices.size());
  for(std::size_t v = 0; v < vertices.size(); ++v)
    position[v] = point_of_lines(
      vertices[v].lines, [&](std::size_t l) -> const Vector_3d& { return lines[l].coefficients; },
      [&](std::size_t l) { return lines[l].is_fixed; });
  return position;
}

// Sorts `edges` by (line, source, target) and removes the repeated ones.
template <class Edge>
void sort_distinct_edges(std::vector<Edge>& edges)
{
  auto key = [](const Edge& e) { return std::tie(e.line, e.source, e.target); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) { return key(x) < key(y); });
  edges.erase(std::unique(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) { return key(x) == key(y); }),
              edges.end());
}

// Merges the sets of `sets` (points of `vertices`, each the union of the lines of its
// members), removes the edges that collapse and the edges that repeat (same line, same points),
// and sorts the edges again by (line, source, target).
template <class Vertex, class Edge>
void apply_point_merges(Union_find<std::size_t>& sets, std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  const std::size_t n = vertices.size();
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
  sort_distinct_edges(remaining);
  vertices.swap(kept);
  edges.swap(remaining);
}

// `lines`, `vertices` and `edges`: those of a `Line_partition_2` (edges with source < target,
// sorted by (line, source, target)). The points whose double coordinates differ by at most
// `tolerance` (in each coordinate, normalized frame) are merged (as the collapse of the edge
// that joins them, if one does), and so are two points joined by two edges on different lines
// (what is left of a triangle of three nearly concurrent lines when one of its edges
// collapses), if they are within 10^4 `tolerance`; the
// merged point is on the lines of its members and is computed from them, so merging is repeated
// (at most 8 times) until no edge is that short. The edges that collapse are removed, the others
// sorted again and made distinct.
template <class Line, class Vertex, class Edge>
void merge_points_that_round_together(const std::vector<Line>& lines, std::vector<Vertex>& vertices,
                                      std::vector<Edge>& edges, double tolerance = 0)
{
  auto close = [](const std::array<double, 2>& p, const std::array<double, 2>& q, double d) {
    return std::abs(p[0] - q[0]) <= d && std::abs(p[1] - q[1]) <= d;
  };
  const double two_gon_tolerance = 1e4 * tolerance;
  for(int round = 0; round < 8; ++round) {
    const std::size_t n = vertices.size();
    const std::vector<std::array<double, 2>> position = point_positions(lines, vertices);
    // The merged points are numbered as their smallest member, in the order of the points: the
    // sets keep their smallest member as representative.
    Union_find<std::size_t> sets(n);
    bool merged = false;
    for(const Edge& e : edges) {
      const auto& p = position[e.source];
      const auto& q = position[e.target];
      if(p == q || close(p, q, tolerance)) {
        sets.unite_at_smallest(e.source, e.target);
        merged = true;
      }
    }
    { // points closer than the tolerance that no edge joins: one hot pixel, as in snap rounding
      std::vector<std::size_t> by_x(n);
      for(std::size_t v = 0; v < n; ++v) by_x[v] = v;
      std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return position[a] < position[b]; });
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = i + 1; j < n && position[by_x[j]][0] - position[by_x[i]][0] <= tolerance; ++j)
          if(close(position[by_x[i]], position[by_x[j]], tolerance)) {
            sets.unite_at_smallest(by_x[i], by_x[j]);
            merged = true;
          }
    }
    {
      std::vector<std::pair<std::size_t, std::size_t>> ends;
      for(const Edge& e : edges) ends.emplace_back(e.source, e.target);
      std::sort(ends.begin(), ends.end());
      for(std::size_t k = 1; k < ends.size(); ++k)
        if(ends[k] == ends[k - 1] && close(position[ends[k].first], position[ends[k].second], two_gon_tolerance)) {
          sets.unite_at_smallest(ends[k].first, ends[k].second);
          merged = true;
        }
    }
    if(!merged) return;
    apply_point_merges(sets, vertices, edges);
  }
}

// Splits each edge e at the points of `splits[e]` ((parameter along e, point) pairs, the
// point not an end of e), in the order of the parameters; each such point gets the edge's line.
// The edges are sorted again by (line, source, target) and made distinct.
template <class Vertex, class Edge>
void split_edges_at_points(std::vector<Vertex>& vertices, std::vector<Edge>& edges,
                           std::vector<std::vector<std::pair<double, std::size_t>>>& splits)
{
  std::vector<Edge> result;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    std::sort(splits[e].begin(), splits[e].end());
    std::size_t from = edges[e].source;
    for(const auto& [t, v] : splits[e]) {
      Edge piece = edges[e];
      piece.source = std::min(from, v);
      piece.target = std::max(from, v);
      if(piece.source != piece.target) result.push_back(piece);
      auto& l = vertices[v].lines;
      if(!std::binary_search(l.begin(), l.end(), edges[e].line)) l.insert(std::lower_bound(l.begin(), l.end(), edges[e].line), edges[e].line);
      from = v;
    }
    Edge last = edges[e];
    last.source = std::min(from, edges[e].target);
    last.target = std::max(from, edges[e].target);
    if(last.source != last.target) result.push_back(last);
  }
  sort_distinct_edges(result);
  edges.swap(result);
}

// Where the rounding puts a point onto an edge: `p` within `reach` of the segment from `s` to
// `t` (double, normalized frame), farther than `margin` from both ends along it. Returns its
// parameter along the segment (0 at `s`, 1 at `t`), if so.
inline std::optional<double> parameter_near_segment(const std::array<double, 2>& p, const std::array<double, 2>& s,
                                                    const std::array<double, 2>& t, double reach, double margin)
{
  const double dx = t[0] - s[0], dy = t[1] - s[1], l2 = dx * dx + dy * dy;
  if(!(l2 > 0)) return std::nullopt;
  const double along = ((p[0] - s[0]) * dx + (p[1] - s[1]) * dy) / l2, length = std::sqrt(l2);
  if(!(along * length > margin && (1 - along) * length > margin)) return std::nullopt;
  if(std::abs(dx * (p[1] - s[1]) - dy * (p[0] - s[0])) > reach * length) return std::nullopt;
  return along;
}

// Iterated snap rounding routes a segment through every point that comes within a pixel of it;
// here, a point that comes within `tolerance` of an edge it does not bound (in double, normalized
// frame, strictly between the ends of the edge) is put on that edge: the edge is split there and
// the point gets the edge's line (the point is then computed from one more line, that passes
// within `tolerance` of it). Returns whether an edge was split; the edges are sorted again.
template <class Line, class Vertex, class Edge>
bool split_edges_at_close_points(const std::vector<Line>& lines, std::vector<Vertex>& vertices,
                                 std::vector<Edge>& edges, double tolerance)
{
  const std::vector<std::array<double, 2>> position = point_positions(lines, vertices);
  std::vector<std::array<double, 4>> segments;
  std::array<double, 2> low{{HUGE_VAL, HUGE_VAL}}, high{{-HUGE_VAL, -HUGE_VAL}};
  for(const Edge& e : edges) {
    const auto& a = position[e.source];
    const auto& b = position[e.target];
    segments.push_back({{a[0], a[1], b[0], b[1]}});
    for(int c = 0; c < 2; ++c) {
      low[c] = std::min({low[c], a[c], b[c]});
      high[c] = std::max({high[c], a[c], b[c]});
    }
  }
  if(!std::isfinite(low[0] + low[1] + high[0] + high[1])) return false; // an invalid partition
  const Segment_grid_2 grid(segments, low, high);
  const int rings = 1 + int(std::ceil(tolerance / grid.cell_size()));
  std::vector<std::vector<std::pair<double, std::size_t>>> splits(edges.size()); // (parameter, point)
  bool split = false;
  for(std::size_t v = 0; v < vertices.size(); ++v) {
    const auto& p = position[v];
    const int x = grid.column(p[0]), y = grid.row(p[1]);
    for(int k = 0; k <= rings; ++k)
      grid.for_each_in_ring(x, y, k, [&](std::uint32_t e) {
        if(edges[e].source == v || edges[e].target == v) return;
        const auto& s = segments[e];
        const std::optional<double> t = parameter_near_segment(p, {s[0], s[1]}, {s[2], s[3]}, tolerance, tolerance);
        if(!t) return;
        if(std::find_if(splits[e].begin(), splits[e].end(), [&](const auto& x) { return x.second == v; }) != splits[e].end())
          return; // listed in several cells
        splits[e].push_back({*t, v});
        split = true;
      });
  }
  if(!split) return false;
  split_edges_at_points(vertices, edges, splits);
  return true;
}

// Iterated snap rounding makes every intersection of the rounded segments a point of the
// result; here, two edges whose double coordinates meet elsewhere than at a common end (decided
// with the exact predicates of `PK`) are split where they meet: at the end of one that is on
// the line of the other, or else at a new point on both their lines. Two edges that leave a
// common point in the same direction are made consecutive: the nearer of their other ends is
// put on the farther edge. Returns whether an edge was split; the edges are sorted again.
template <class PK, class Line, class Vertex, class Edge>
bool split_edges_at_crossings(const std::vector<Line>& lines, std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  std::vector<std::array<double, 2>> position = point_positions(lines, vertices);
  std::vector<std::array<std::size_t, 2>> ends(edges.size());
  for(std::size_t e = 0; e < edges.size(); ++e) {
    ends[e] = {{edges[e].source, edges[e].target}};
    for(std::size_t v : ends[e])
      if(!std::isfinite(position[v][0] + position[v][1])) return false; // an invalid partition
  }
  const auto crossings = crossing_edge_pairs<PK>(position, ends, true, [](const auto&, const auto&) { return true; });
  if(crossings.empty()) return false;
  std::vector<std::vector<std::pair<double, std::size_t>>> splits(edges.size()); // (parameter, point)
  auto put_on = [&](std::size_t v, std::size_t e) {
    const auto& a = position[edges[e].source];
    const auto& b = position[edges[e].target];
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    // (an edge whose ends round to one point gets parameter 0, not a NaN that would break the sort)
    const double t = l2 > 0 ? ((position[v][0] - a[0]) * dx + (position[v][1] - a[1]) * dy) / l2 : 0.;
    auto& list = splits[e];
    if(std::find_if(list.begin(), list.end(), [&](const auto& x) { return x.second == v; }) == list.end())
      list.push_back({t, v});
  };
  auto on_line = [&](std::size_t v, std::size_t line) {
    return std::binary_search(vertices[v].lines.begin(), vertices[v].lines.end(), line);
  };
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> new_point; // line pair -> point
  for(const auto& [e, f] : crossings) {
    if(edges[e].line == edges[f].line) continue; // (distinct edges of a line only meet at ends)
    std::size_t common = std::size_t(-1), shared = 0;
    for(std::size_t a : ends[e])
      for(std::size_t b : ends[f])
        if(a == b) { common = a; ++shared; }
    if(shared == 2) continue; // two points joined on two lines: merged, or left (see above)
    if(shared == 1) {
      const std::size_t oe = ends[e][0] == common ? ends[e][1] : ends[e][0];
      const std::size_t of = ends[f][0] == common ? ends[f][1] : ends[f][0];
      auto d2 = [&](std::size_t v) {
        return std::pow(position[v][0] - position[common][0], 2) + std::pow(position[v][1] - position[common][1], 2);
      };
      if(d2(oe) <= d2(of)) put_on(oe, f); else put_on(of, e);
      continue;
    }
    bool touched = false;
    for(std::size_t v : ends[f]) if(on_line(v, edges[e].line)) { put_on(v, e); touched = true; }
    for(std::size_t v : ends[e]) if(on_line(v, edges[f].line)) { put_on(v, f); touched = true; }
    if(touched) continue;
    const auto key = std::minmax(edges[e].line, edges[f].line);
    auto [it, inserted] = new_point.emplace(key, vertices.size());
    if(inserted) {
      Vertex v;
      v.lines = {key.first, key.second};
      vertices.push_back(v);
      position.push_back(point_positions(lines, std::vector<Vertex>{v}).front()); // its lines' meet
    }
    put_on(it->second, e);
    put_on(it->second, f);
  }
  split_edges_at_points(vertices, edges, splits);
  return true;
}

// Points that come closer than `tolerance` (normalized frame, in double) to another point they
// are joined to, or to an edge they do not bound, are merged with it or put on it, and edges
// that meet elsewhere than at a common end are split where they meet, until none does (at most
// 8 rounds): the rounding of iterated snap rounding, on points computed from lines. `PK`: the
// exact predicates kernel of the geometric traits.
template <class PK, class Line, class Vertex, class Edge>
void round_points_apart(const std::vector<Line>& lines, std::vector<Vertex>& vertices, std::vector<Edge>& edges,
                        double tolerance)
{
  for(int round = 0; round < 8; ++round) {
    merge_points_that_round_together(lines, vertices, edges, tolerance);
    if(!split_edges_at_close_points(lines, vertices, edges, tolerance) &&
       !split_edges_at_crossings<PK>(lines, vertices, edges))
      return;
  }
  merge_points_that_round_together(lines, vertices, edges, tolerance);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_MERGE_ROUNDED_POINTS_2_H

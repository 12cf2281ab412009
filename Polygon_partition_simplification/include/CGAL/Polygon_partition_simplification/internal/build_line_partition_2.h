// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_BUILD_LINE_PARTITION_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_BUILD_LINE_PARTITION_2_H

// From exact segments to a partition in line representation: the segments are inserted in
// an exact CGAL arrangement (which finds every intersection and merges overlaps); each of
// its edges gets the supporting line of its segment, identified exactly (collinear pieces
// share one line); edges that dangle or bridge (same face on both sides) are dropped and
// points on a single line (where two collinear edges meet) are removed by joining their edges.

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Enclosing_rectangle_2.h>
#include <CGAL/Polygon_partition_simplification/internal/nearest_double.h>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

struct Exact_piece
{
  Exact_kernel::Segment_2 segment;
  bool is_fixed = false; // a side of a kinetic bounding box
  // When known, the index of the piece's line among the lines given to
  // build_line_partition() (`group_lines`): pieces with the same index are on that line.
  std::size_t line_group = std::size_t(-1);
};

// Exact canonical form of a line: (1, b/a, c/a) when |a| >= |b|, else (a/b, 1, c/b) (so that
// no coefficient overflows: b/a of a nearly horizontal line can be beyond the doubles), in the
// exact number type directly: every line's exact equation is needed (for the nearest doubles
// of its coefficients), and evaluating it through the lazy kernel made each of its operations
// a node of its own, synchronized on its own (a system call each, with threads).
struct Line_key
{
  bool divided_by_b; // |a| < |b|: the key is (u, 1, v) = (a, b, c) / b, else (1, u, v) = (a, b, c) / a
  Exact_number u, v;

  Line_key(const Exact_number& a, const Exact_number& b, const Exact_number& c)
  {
    divided_by_b = CGAL::compare(CGAL::abs(a), CGAL::abs(b)) == CGAL::SMALLER;
    if(divided_by_b) { u = a / b; v = c / b; }
    else { u = b / a; v = c / a; }
  }
  // the line through (x0, y0) and (x1, y1), which differ
  explicit Line_key(const std::array<double, 4>& c)
    : Line_key(Exact_number(c[1]) - Exact_number(c[3]), Exact_number(c[2]) - Exact_number(c[0]),
               Exact_number(c[0]) * Exact_number(c[3]) - Exact_number(c[2]) * Exact_number(c[1])) {}
  bool operator<(const Line_key& o) const
  {
    if(divided_by_b != o.divided_by_b) return divided_by_b < o.divided_by_b;
    const CGAL::Comparison_result cu = CGAL::compare(u, o.u);
    if(cu != CGAL::EQUAL) return cu == CGAL::SMALLER;
    return CGAL::compare(v, o.v) == CGAL::SMALLER;
  }
};

inline Line_key key_of(const Exact_kernel::Segment_2& s)
{
  const Exact_kernel::Line_2 lazy(s.source(), s.target());
  const auto& line = CGAL::exact(lazy); // a reference into `lazy`
  return Line_key(line.a(), line.b(), line.c());
}

// The points of a partition are computed in double from their lines, and two of them must
// not coincide. Distinct exact points can round to the same coordinates: the end of a segment
// whose line passes within a rounding error of a corner of the bounding box (whose corners
// are rounded), next to that corner; or two intersections of nearly identical lines. Points
// that coincide so and are joined by an edge are merged, as the collapse of that edge: the
// merged point is on all their lines (on two sides of the box, it is the corner).
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
  std::vector<std::size_t> parent(n);
  for(std::size_t v = 0; v < n; ++v) parent[v] = v;
  auto find = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  bool merged = false;
  for(const Edge& e : edges)
    if(position[e.source] == position[e.target]) {
      const std::size_t a = find(e.source), b = find(e.target);
      if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
      merged = true;
    }
  if(!merged) return;
  // the merged points keep the number of their smallest member; the others are dropped
  std::vector<std::size_t> new_index(n, std::size_t(-1));
  std::vector<Vertex> kept;
  for(std::size_t v = 0; v < n; ++v)
    if(find(v) == v) {
      new_index[v] = kept.size();
      kept.push_back(vertices[v]);
    }
  for(std::size_t v = 0; v < n; ++v)
    if(find(v) != v) {
      auto& l = kept[new_index[find(v)]].lines;
      l.insert(l.end(), vertices[v].lines.begin(), vertices[v].lines.end());
    }
  for(Vertex& v : kept) {
    std::sort(v.lines.begin(), v.lines.end());
    v.lines.erase(std::unique(v.lines.begin(), v.lines.end()), v.lines.end());
  }
  std::vector<Edge> remaining;
  for(Edge e : edges) {
    e.source = new_index[find(e.source)];
    e.target = new_index[find(e.target)];
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

// `metric_segments`: the segments the metrics of the lines are accumulated from (the pieces
// themselves when empty; the fixed pieces always). `group_lines`: lines given by two points
// in double precision, on which the pieces and metric segments with a `line_group` lie
// exactly. Identifying the line of a piece from its own endpoints, which are intersections of
// lines (the ends of a kinetic extent, deep in the lazy kernel's expression DAG), made the
// exact evaluation of these endpoints the most expensive part of a kinetic partition (for
// pieces on the same line, whose keys are equal, the interval filters never decide).
template <class GeomTraits>
Line_partition_2<GeomTraits>
build_line_partition(const std::vector<Exact_piece>& pieces,
                     const std::vector<Exact_piece>& metric_segments,
                     const typename Line_partition_2<GeomTraits>::Frame& frame,
                     const std::vector<std::array<double, 4>>& group_lines = {})
{
  using Partition = Line_partition_2<GeomTraits>;
  using Traits = CGAL::Arr_consolidated_curve_data_traits_2<
    CGAL::Arr_segment_traits_2<Exact_kernel>, std::size_t>;
  using Arrangement = CGAL::Arrangement_2<Traits>;
  using Vertex_handle = typename Arrangement::Vertex_const_handle;

  // Lines in the exact order of their canonical keys: indices do not depend on input order.
  // Keys are computed per piece, or once per group of pieces known to be on one line (from the
  // group's double endpoints); the arrangement carries each piece's line to its edges
  // (overlapping pieces are on the same line, so an edge has one line).
  using Line_iterator = std::map<Line_key, std::size_t>::iterator;
  std::map<Line_key, std::size_t> line_index;
  std::vector<Line_iterator> group_line(group_lines.size(), line_index.end());
  auto line_of = [&](const Exact_piece& p) {
    if(p.line_group == std::size_t(-1)) return line_index.emplace(key_of(p.segment), 0).first;
    Line_iterator& it = group_line.at(p.line_group);
    if(it == line_index.end()) {
      it = line_index.emplace(Line_key(group_lines[p.line_group]), 0).first;
    }
    return it;
  };
  std::vector<Line_iterator> piece_line;
  piece_line.reserve(pieces.size());
  for(const Exact_piece& p : pieces) piece_line.push_back(line_of(p));
  std::vector<Line_iterator> metric_line;
  metric_line.reserve(metric_segments.size());
  for(const Exact_piece& s : metric_segments) metric_line.push_back(line_of(s));
  if(line_index.empty())
    throw Input_error(Input_error_code::EMPTY_INPUT, "the input has no edge");
  std::vector<typename Partition::Line> lines;
  lines.reserve(line_index.size());
  for(auto& [key, index] : line_index) {
    index = lines.size();
    typename Partition::Line line;
    // a x + b y + c = 0 in input coordinates becomes, in the normalized frame,
    // a x' + b y' + (a cx + b cy + c) / s = 0.
    const Exact_number a = key.divided_by_b ? key.u : Exact_number(1), b = key.divided_by_b ? Exact_number(1) : key.u,
                       c = key.v;
    const Exact_number c_frame = (a * Exact_number(frame.center_x) + b * Exact_number(frame.center_y) + c) / Exact_number(frame.scale);
    line.coefficients = normalized_line({double_of(a), double_of(b), double_of(c_frame)});
    lines.push_back(line);
  }
  for(std::size_t i = 0; i < pieces.size(); ++i)
    if(pieces[i].is_fixed) lines[piece_line[i]->second].is_fixed = true;

  Arrangement arrangement;
  {
    std::vector<typename Traits::Curve_2> curves;
    curves.reserve(pieces.size());
    for(std::size_t i = 0; i < pieces.size(); ++i)
      curves.emplace_back(pieces[i].segment, piece_line[i]->second);
    CGAL::insert(arrangement, curves.begin(), curves.end());
  }

  // Metrics: from the given segments, or from the pieces themselves, added line by line in
  // the order of their (nearest double, normalized) endpoints, so that the sums, which are
  // rounded, do not depend on the order of the input.
  {
    struct Metric_term { std::size_t line; std::array<double, 4> ends; };
    std::vector<Metric_term> terms;
    auto add = [&](const Exact_kernel::Segment_2& s, std::size_t index) {
      auto normalized = [&](const Exact_kernel::Point_2& p) {
        return std::array<double, 2>{(double_of(p.x()) - frame.center_x) / frame.scale,
                                     (double_of(p.y()) - frame.center_y) / frame.scale};
      };
      std::array<double, 2> p = normalized(s.source()), q = normalized(s.target());
      if(q < p) std::swap(p, q);
      terms.push_back({index, {p[0], p[1], q[0], q[1]}});
    };
    for(std::size_t i = 0; i < metric_segments.size(); ++i) add(metric_segments[i].segment, metric_line[i]->second);
    for(std::size_t i = 0; i < pieces.size(); ++i)
      if(metric_segments.empty() || pieces[i].is_fixed) add(pieces[i].segment, piece_line[i]->second);
    std::sort(terms.begin(), terms.end(), [](const Metric_term& a, const Metric_term& b) {
      return std::tie(a.line, a.ends) < std::tie(b.line, b.ends);
    });
    for(const Metric_term& t : terms) {
      lines[t.line].metric.add_segment(t.ends[0], t.ends[1], t.ends[2], t.ends[3]);
      ++lines[t.line].number_of_segments;
    }
  }

  // Graph of the arrangement, with the line of each edge; dangling edges are pruned.
  std::map<Vertex_handle, std::size_t> vertex_index;
  std::vector<Vertex_handle> arrangement_vertices;
  for(auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
    vertex_index.emplace(v, arrangement_vertices.size());
    arrangement_vertices.push_back(v);
  }
  struct Graph_edge { std::size_t u, v, line; bool alive; };
  std::vector<Graph_edge> graph_edges;
  std::vector<std::vector<std::size_t>> incident(arrangement_vertices.size());
  for(auto h = arrangement.edges_begin(); h != arrangement.edges_end(); ++h) {
    const std::size_t u = vertex_index.at(h->source()), v = vertex_index.at(h->target());
    incident[u].push_back(graph_edges.size());
    incident[v].push_back(graph_edges.size());
    // an edge with the same face on both sides (a bridge or an antenna) bounds no cell
    graph_edges.push_back({u, v, h->curve().data().front(), h->face() != h->twin()->face()});
  }
  std::vector<std::size_t> degree(incident.size());
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < incident.size(); ++v) {
    degree[v] = 0;
    for(std::size_t e : incident[v]) degree[v] += graph_edges[e].alive ? 1 : 0;
    if(degree[v] == 1) stack.push_back(v);
  }
  while(!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    for(std::size_t e : incident[v]) {
      if(!graph_edges[e].alive) continue;
      graph_edges[e].alive = false;
      for(std::size_t w : {graph_edges[e].u, graph_edges[e].v})
        if(--degree[w] == 1) stack.push_back(w);
    }
  }

  // Points: vertices on at least two lines. Edges: chains through single-line vertices.
  std::vector<std::vector<std::size_t>> vertex_lines(incident.size());
  for(std::size_t v = 0; v < incident.size(); ++v) {
    for(std::size_t e : incident[v])
      if(graph_edges[e].alive) vertex_lines[v].push_back(graph_edges[e].line);
    std::sort(vertex_lines[v].begin(), vertex_lines[v].end());
    vertex_lines[v].erase(std::unique(vertex_lines[v].begin(), vertex_lines[v].end()),
                          vertex_lines[v].end());
  }
  // Points are numbered in the order of their (sorted) line sets: input-order independent.
  std::vector<std::size_t> point_vertices;
  for(std::size_t v = 0; v < incident.size(); ++v)
    if(vertex_lines[v].size() >= 2) point_vertices.push_back(v);
  std::sort(point_vertices.begin(), point_vertices.end(), [&](std::size_t x, std::size_t y) {
    if(vertex_lines[x] != vertex_lines[y]) return vertex_lines[x] < vertex_lines[y];
    return arrangement_vertices[x]->point() < arrangement_vertices[y]->point();
  });
  std::vector<std::size_t> point_index(incident.size(), std::size_t(-1));
  std::vector<typename Partition::Vertex> vertices;
  for(std::size_t v : point_vertices) {
    point_index[v] = vertices.size();
    vertices.push_back({vertex_lines[v]});
  }
  std::vector<typename Partition::Edge> edges;
  std::vector<bool> visited(graph_edges.size(), false);
  for(std::size_t start : point_vertices)
    for(std::size_t e0 : incident[start]) {
      if(!graph_edges[e0].alive || visited[e0]) continue;
      std::size_t v = start, e = e0;
      for(;;) {
        visited[e] = true;
        v = graph_edges[e].u == v ? graph_edges[e].v : graph_edges[e].u;
        if(point_index[v] != std::size_t(-1)) break;
        std::size_t next = std::size_t(-1); // a single-line vertex has exactly one other edge
        for(std::size_t f : incident[v])
          if(graph_edges[f].alive && f != e) next = f;
        e = next;
      }
      std::size_t s = point_index[start], t = point_index[v];
      if(s > t) std::swap(s, t);
      edges.push_back({graph_edges[e0].line, s, t});
    }
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
    return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
  });
  if(edges.empty())
    throw Input_error(Input_error_code::NO_CELL,
                      "the input bounds no cell: every edge dangles; give closed polygons or "
                      "segments that meet");
  merge_points_that_round_together(lines, vertices, edges);

  // Drop the lines no edge uses and number the others by decreasing spread of their segment
  // endpoints (which rigid motions and scalings do not change), then by their exact equation:
  // the numbering, and the order of everything that follows it, depend neither on the order
  // of the input nor on its position.
  std::vector<std::size_t> used_lines;
  {
    std::vector<bool> used(lines.size(), false);
    for(const auto& e : edges) used[e.line] = true;
    for(std::size_t l = 0; l < lines.size(); ++l)
      if(used[l]) used_lines.push_back(l);
  }
  auto spread = [&](std::size_t l) {
    const Line_metric& m = lines[l].metric;
    return m(2, 2) > 0 ? m(0, 0) + m(1, 1) - (m(0, 2) * m(0, 2) + m(1, 2) * m(1, 2)) / m(2, 2) : 0.;
  };
  std::stable_sort(used_lines.begin(), used_lines.end(),
                   [&](std::size_t x, std::size_t y) { return spread(x) > spread(y); });
  std::vector<std::size_t> new_line(lines.size(), std::size_t(-1));
  std::vector<typename Partition::Line> kept;
  for(std::size_t l : used_lines) { new_line[l] = kept.size(); kept.push_back(lines[l]); }
  for(auto& e : edges) e.line = new_line[e.line];
  // (a point can be on a line left without edges: the only edge of that line at the point
  // collapsed when points that round together merged; the point is then on its other lines)
  for(auto& v : vertices) {
    for(auto& l : v.lines) l = new_line[l];
    v.lines.erase(std::remove(v.lines.begin(), v.lines.end(), std::size_t(-1)), v.lines.end());
    std::sort(v.lines.begin(), v.lines.end());
  }
  // points by their line sets, edges by (line, points)
  std::vector<std::size_t> order(vertices.size());
  for(std::size_t v = 0; v < order.size(); ++v) order[v] = v;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return vertices[x].lines < vertices[y].lines; });
  std::vector<std::size_t> new_vertex(vertices.size());
  std::vector<typename Partition::Vertex> sorted_vertices;
  for(std::size_t v : order) { new_vertex[v] = sorted_vertices.size(); sorted_vertices.push_back(vertices[v]); }
  for(auto& e : edges) {
    e.source = new_vertex[e.source];
    e.target = new_vertex[e.target];
    if(e.source > e.target) std::swap(e.source, e.target);
  }
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
    return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
  });
  return Partition(frame, std::move(kept), std::move(sorted_vertices), std::move(edges));
}

// The normalized frame of a set of points: center and half-diagonal of their smallest
// enclosing rectangle (a unit scale when they all coincide).
template <class Frame>
Frame frame_of(const Enclosing_rectangle_2& rectangle)
{
  Frame frame;
  frame.center_x = rectangle.center[0];
  frame.center_y = rectangle.center[1];
  frame.scale = rectangle.half_diagonal() > 0 ? rectangle.half_diagonal() : 1.;
  return frame;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_BUILD_LINE_PARTITION_2_H

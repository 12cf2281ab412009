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
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Piece_arrangement_2.h>
#include <CGAL/Polygon_partition_simplification/internal/merge_rounded_points_2.h>
#include <CGAL/Polygon_partition_simplification/internal/nearest_double.h>
#include <CGAL/Polygon_partition_simplification/internal/remove_defective_edges_2.h>
#include <CGAL/Polygon_partition_simplification/internal/split_pinched_cells_2.h>

#include <CGAL/Arrangement_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// A segment of `EK`, the exact constructions kernel of the geometric traits.
template <class EK>
struct Exact_piece
{
  typename EK::Segment_2 segment;
  bool is_fixed = false; // a side of a kinetic bounding box
  // When known, the index of the piece's line among the lines given to
  // build_line_partition() (`group_lines`): pieces with the same index are on that line.
  std::size_t line_group = std::size_t(-1);
};

// Exact canonical form of a line: (1, b/a, c/a) when |a| >= |b|, else (a/b, 1, c/b) (so that
// no coefficient overflows: b/a of a nearly horizontal line can be beyond the doubles), in the
// exact number type directly: every line's exact equation is needed (for the nearest doubles
// of its coefficients), and through the lazy kernel each of its operations would be a node of
// its own, evaluated (and, with threads, synchronized) on its own. `ET`: the exact number type of
// the exact constructions kernel (behind its lazy number type, if it is lazy).
template <class ET>
struct Line_key
{
  bool divided_by_b; // |a| < |b|: the key is (u, 1, v) = (a, b, c) / b, else (1, u, v) = (a, b, c) / a
  ET u, v;

  Line_key(const ET& a, const ET& b, const ET& c)
  {
    divided_by_b = CGAL::compare(CGAL::abs(a), CGAL::abs(b)) == CGAL::SMALLER;
    if(divided_by_b) { u = a / b; v = c / b; }
    else { u = b / a; v = c / a; }
  }
  // the line through (x0, y0) and (x1, y1), which differ
  explicit Line_key(const std::array<double, 4>& c)
    : Line_key(ET(c[1]) - ET(c[3]), ET(c[2]) - ET(c[0]), ET(c[0]) * ET(c[3]) - ET(c[2]) * ET(c[1])) {}
  bool operator<(const Line_key& o) const
  {
    if(divided_by_b != o.divided_by_b) return divided_by_b < o.divided_by_b;
    const CGAL::Comparison_result cu = CGAL::compare(u, o.u);
    if(cu != CGAL::EQUAL) return cu == CGAL::SMALLER;
    return CGAL::compare(v, o.v) == CGAL::SMALLER;
  }
};

template <class EK>
Line_key<Exact_number<EK>> key_of(const typename EK::Segment_2& s)
{
  const typename EK::Line_2 lazy(s.source(), s.target());
  const auto& line = exact_value<EK>(lazy); // a reference into `lazy`
  return Line_key<Exact_number<EK>>(line.a(), line.b(), line.c());
}

// The lines of the pieces and of the metric segments of build_line_partition(), numbered in
// the exact order of their canonical keys (so the numbers do not depend on the order of the
// input), with their coefficients in the normalized frame and `is_fixed` set from the pieces.
template <class Line>
struct Piece_lines
{
  std::vector<Line> lines;
  std::vector<std::size_t> piece_line;  // per piece, the index of its line
  std::vector<std::size_t> metric_line; // per metric segment, the index of its line
};

// Keys are computed per piece, or once per group of pieces known to be on one line (from the
// group's double endpoints in `group_lines`). Throws Input_error (EMPTY_INPUT) when there is
// no line.
template <class Line, class Frame, class EK>
Piece_lines<Line> identify_lines(const std::vector<Exact_piece<EK>>& pieces,
                                 const std::vector<Exact_piece<EK>>& metric_segments, const Frame& frame,
                                 const std::vector<std::array<double, 4>>& group_lines)
{
  using ET = Exact_number<EK>;
  using Key = Line_key<ET>;
  using Line_iterator = typename std::map<Key, std::size_t>::iterator;
  std::map<Key, std::size_t> line_index;
  std::vector<Line_iterator> group_line(group_lines.size(), line_index.end());
  auto line_of = [&](const Exact_piece<EK>& p) {
    if(p.line_group == std::size_t(-1)) return line_index.emplace(key_of<EK>(p.segment), 0).first;
    Line_iterator& it = group_line.at(p.line_group);
    if(it == line_index.end()) {
      it = line_index.emplace(Key(group_lines[p.line_group]), 0).first;
    }
    return it;
  };
  std::vector<Line_iterator> piece_line;
  piece_line.reserve(pieces.size());
  for(const Exact_piece<EK>& p : pieces) piece_line.push_back(line_of(p));
  std::vector<Line_iterator> metric_line;
  metric_line.reserve(metric_segments.size());
  for(const Exact_piece<EK>& s : metric_segments) metric_line.push_back(line_of(s));
  if(line_index.empty())
    throw Input_error(Input_error_code::EMPTY_INPUT, "the input has no edge");
  Piece_lines<Line> result;
  result.lines.reserve(line_index.size());
  for(auto& [key, index] : line_index) {
    index = result.lines.size();
    Line line;
    // a x + b y + c = 0 in input coordinates becomes, in the normalized frame,
    // a x' + b y' + (a cx + b cy + c) / s = 0.
    const ET a = key.divided_by_b ? key.u : ET(1), b = key.divided_by_b ? ET(1) : key.u, c = key.v;
    const ET c_frame = (a * ET(frame.center_x) + b * ET(frame.center_y) + c) / ET(frame.scale);
    line.coefficients = normalized_line({double_of(a), double_of(b), double_of(c_frame)});
    result.lines.push_back(line);
  }
  for(const Line_iterator& it : piece_line) result.piece_line.push_back(it->second);
  for(const Line_iterator& it : metric_line) result.metric_line.push_back(it->second);
  for(std::size_t i = 0; i < pieces.size(); ++i)
    if(pieces[i].is_fixed) result.lines[result.piece_line[i]].is_fixed = true;
  return result;
}

// The metrics of the lines: from the metric segments, or from the pieces themselves when there
// are none (and from the fixed pieces always), added line by line in the order of their
// (nearest double, normalized) endpoints, so that the sums, which are rounded, do not depend on
// the order of the input.
template <class Line, class Frame, class EK>
void accumulate_metrics(std::vector<Line>& lines, const Frame& frame, const std::vector<Exact_piece<EK>>& pieces,
                        const std::vector<std::size_t>& piece_line, const std::vector<Exact_piece<EK>>& metric_segments,
                        const std::vector<std::size_t>& metric_line)
{
  struct Metric_term { std::size_t line; std::array<double, 4> ends; };
  std::vector<Metric_term> terms;
  auto add = [&](const typename EK::Segment_2& s, std::size_t index) {
    auto normalized = [&](const typename EK::Point_2& p) {
      return std::array<double, 2>{(double_of(p.x()) - frame.center_x) / frame.scale,
                                   (double_of(p.y()) - frame.center_y) / frame.scale};
    };
    std::array<double, 2> p = normalized(s.source()), q = normalized(s.target());
    if(q < p) std::swap(p, q);
    terms.push_back({index, {p[0], p[1], q[0], q[1]}});
  };
  for(std::size_t i = 0; i < metric_segments.size(); ++i) add(metric_segments[i].segment, metric_line[i]);
  for(std::size_t i = 0; i < pieces.size(); ++i)
    if(metric_segments.empty() || pieces[i].is_fixed) add(pieces[i].segment, piece_line[i]);
  std::sort(terms.begin(), terms.end(), [](const Metric_term& a, const Metric_term& b) {
    return std::tie(a.line, a.ends) < std::tie(b.line, b.ends);
  });
  for(const Metric_term& t : terms) {
    lines[t.line].metric.add_segment(t.ends[0], t.ends[1], t.ends[2], t.ends[3]);
    ++lines[t.line].number_of_segments;
  }
}

// Numbers `lines` by decreasing spread of their segment endpoints (which rigid motions and
// scalings do not change), then by their exact equation (their order in `lines`), in
// `vertices` and `edges` too (the lines of each point sorted again, the edges sorted by (line,
// source, target)). The points of several lines are computed from them in the order of their
// numbers (see point_of_lines()): with the final numbers from here on, the points that the
// rounding checks are the points of the result.
template <class Line, class Vertex, class Edge>
void number_lines_canonically(std::vector<Line>& lines, std::vector<Vertex>& vertices, std::vector<Edge>& edges)
{
  auto spread = [&](std::size_t l) {
    const Line_metric& m = lines[l].metric;
    return m(2, 2) > 0 ? m(0, 0) + m(1, 1) - (m(0, 2) * m(0, 2) + m(1, 2) * m(1, 2)) / m(2, 2) : 0.;
  };
  std::vector<std::size_t> order(lines.size());
  for(std::size_t l = 0; l < order.size(); ++l) order[l] = l;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return spread(x) > spread(y); });
  std::vector<std::size_t> new_line(lines.size());
  std::vector<Line> sorted;
  sorted.reserve(lines.size());
  for(std::size_t l : order) { new_line[l] = sorted.size(); sorted.push_back(lines[l]); }
  lines.swap(sorted);
  for(auto& v : vertices) {
    for(auto& l : v.lines) l = new_line[l];
    std::sort(v.lines.begin(), v.lines.end());
  }
  for(auto& e : edges) e.line = new_line[e.line];
  std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) {
    return std::tie(x.line, x.source, x.target) < std::tie(y.line, y.source, y.target);
  });
}

// The partition of `lines` (numbered by number_lines_canonically()), `vertices` and `edges` in
// canonical order: the lines no edge uses are dropped (the others keep their order); the points
// are numbered by their line sets, the edges by (line, points). The numbering, and the order of
// everything that follows it, depend neither on the order of the input nor on its position.
template <class Partition>
Partition canonical_partition(const typename Partition::Frame& frame, const std::vector<typename Partition::Line>& lines,
                              std::vector<typename Partition::Vertex> vertices, std::vector<typename Partition::Edge> edges,
                              const typename Partition::Geom_traits& gt)
{
  std::vector<bool> used(lines.size(), false);
  for(const auto& e : edges) used[e.line] = true;
  std::vector<std::size_t> new_line(lines.size(), std::size_t(-1));
  std::vector<typename Partition::Line> kept;
  for(std::size_t l = 0; l < lines.size(); ++l)
    if(used[l]) { new_line[l] = kept.size(); kept.push_back(lines[l]); }
  for(auto& e : edges) e.line = new_line[e.line];
  // (a point can be on a line left without edges: the only edge of that line at the point
  // collapsed when points that round together merged; the point is then on its other lines)
  for(auto& v : vertices) {
    for(auto& l : v.lines) l = new_line[l];
    v.lines.erase(std::remove(v.lines.begin(), v.lines.end(), std::size_t(-1)), v.lines.end());
  }
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
  return Partition(frame, std::move(kept), std::move(sorted_vertices), std::move(edges), gt);
}

// The distance (normalized frame) below which two points are merged and a point is put on an
// edge: 1e-13 half-diagonals (points computed in double from nearly concurrent lines are off by
// more than that only at angles below 1e-3), or 8 units in the last place of the input
// coordinates of the frame, if larger (points closer than that in the normalized frame would
// coincide or swap in input coordinates).
template <class Frame>
double merge_tolerance(const Frame& frame)
{
  const double largest = std::max(std::abs(frame.center_x), std::abs(frame.center_y)) + 2 * frame.scale;
  const double ulp = std::nextafter(largest, HUGE_VAL) - largest;
  return std::max(1e-13, 8 * ulp / frame.scale);
}

// `metric_segments`: the segments the metrics of the lines are accumulated from (the pieces
// themselves when empty; the fixed pieces always). `group_lines`: lines given by two points
// in double precision, on which the pieces and metric segments with a `line_group` lie
// exactly. Identifying the line of a piece from its own endpoints, which are intersections of
// lines (the ends of a kinetic extent, deep in the lazy kernel's expression DAG), would need
// the exact evaluation of these endpoints (for pieces on the same line, whose keys are equal,
// the interval filters never decide), the most expensive part of a kinetic partition.
// `gt`: the geometric traits of the result, whose exact constructions kernel is `EK`.
// `corner_rays`: the ends of pieces that may go on to split a cell that is not a simple polygon
// (see split_pinched_cells_2.h); `extended`, if given, is set to the number of them that did.
// With `removed` (a kinetic partition, whose pieces are the grown segments), the defects that
// the rounding leaves are removed (see remove_defective_edges_2.h) and `removed` is set to the
// number of edges removed for them; without it (pieces given by the user: polygons, an
// arrangement), nothing the user gave is removed and the partition is returned as it is.
template <class GeomTraits, class EK>
Line_partition_2<GeomTraits>
build_line_partition(const std::vector<Exact_piece<EK>>& pieces,
                     const std::vector<Exact_piece<EK>>& metric_segments,
                     const typename Line_partition_2<GeomTraits>::Frame& frame,
                     const typename Line_partition_2<GeomTraits>::Geom_traits& gt,
                     const std::vector<std::array<double, 4>>& group_lines = {},
                     const std::vector<Corner_ray<EK>>& corner_rays = {}, std::size_t* extended = nullptr,
                     std::size_t* removed = nullptr)
{
  using Partition = Line_partition_2<GeomTraits>;
  static_assert(std::is_same<EK, typename Partition::Geom_traits::Exact_constructions_kernel>::value,
                "the pieces are in the exact constructions kernel of the geometric traits");
  // 1. The supporting lines, identified exactly: collinear pieces share one line.
  Piece_lines<typename Partition::Line> lines =
    identify_lines<typename Partition::Line>(pieces, metric_segments, frame, group_lines);
  // 2. The exact arrangement of the pieces, which finds every intersection and merges overlaps;
  //    each piece carries its line to its edges; the cells that are not simple polygons split.
  Piece_arrangement<EK> arrangement;
  {
    std::vector<typename Piece_traits<EK>::Curve_2> curves;
    curves.reserve(pieces.size());
    for(std::size_t i = 0; i < pieces.size(); ++i)
      curves.emplace_back(pieces[i].segment, lines.piece_line[i]);
    CGAL::insert(arrangement, curves.begin(), curves.end());
  }
  {
    const Point_rounding rounding{frame.center_x, frame.center_y, frame.scale, merge_tolerance(frame)};
    Input_on_line<EK> input_on_line(lines.lines.size());
    for(std::size_t i = 0; i < metric_segments.size(); ++i)
      input_on_line[lines.metric_line[i]].push_back(metric_segments[i].segment);
    const std::size_t added = split_pinched_cells<EK>(arrangement, corner_rays, lines.piece_line, rounding, input_on_line);
    if(extended != nullptr) *extended = added;
  }
  // 3. The fidelity metrics of the lines.
  accumulate_metrics(lines.lines, frame, pieces, lines.piece_line, metric_segments, lines.metric_line);
  // 4. The points and edges of the arrangement that bound cells.
  Piece_graph<EK> graph = piece_graph(arrangement);
  prune_dangling_edges(graph);
  Points_and_edges<Partition> parts = points_and_chained_edges<Partition>(graph);
  // 5. Points whose double coordinates come too close to another point or to an edge, merged
  //    with it or put on it, and edges whose double coordinates cross, split where they do (see
  //    merge_rounded_points_2.h), with the lines in their final order.
  number_lines_canonically(lines.lines, parts.vertices, parts.edges);
  round_points_apart<typename Partition::Geom_traits::Exact_predicates_kernel>(lines.lines, parts.vertices, parts.edges, merge_tolerance(frame));
  //    In a kinetic partition, what the rounds could not settle is removed (an edge at a time,
  //    the shortest first).
  if(removed != nullptr)
    *removed = remove_defective_edges<typename Partition::Geom_traits>(lines.lines, parts.vertices, parts.edges);
  // 6. Numbering independent of the input order and position.
  return canonical_partition<Partition>(frame, lines.lines, std::move(parts.vertices), std::move(parts.edges), gt);
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

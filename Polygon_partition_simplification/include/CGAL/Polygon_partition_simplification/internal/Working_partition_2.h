// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WORKING_PARTITION_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WORKING_PARTITION_2_H

// The form of a partition in line representation that the simplification works on, and the
// copies from a `Line_partition_2` and back. It holds the same lines, points and edges, with
// 32-bit indices, the lines of a point in a small inline vector (no allocation up to four), the
// state of each line during a round (`Line_state`: frozen, merged members), and each edge with
// its smaller point first.

#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_energy_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Line_geometry_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Partition_validity_2.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

using Index = std::uint32_t;

// the lines through a point (two, or a few after points merged): no allocation up to four
using Point_lines = boost::container::small_vector<Index, 4>;

struct Working_partition
{
  std::vector<Line_state> lines;
  std::vector<Point_lines> vertex_lines; // sorted, distinct
  std::vector<std::array<Index, 3>> edges;      // line, u < v

  std::array<double, 2> point(Index v) const
  {
    return point_of_lines(
      vertex_lines[v], [this](std::size_t l) -> const Vector_3d& { return lines[l].coefficients; },
      [this](std::size_t l) { return lines[l].is_fixed; });
  }
};

// Working_partition as seen by partition_defect()
struct Working_partition_view
{
  const Working_partition& w;
  std::size_t number_of_lines() const { return w.lines.size(); }
  const Vector_3d& coefficients(std::size_t l) const { return w.lines[l].coefficients; }
  bool is_fixed(std::size_t l) const { return w.lines[l].is_fixed; }
  std::size_t number_of_vertices() const { return w.vertex_lines.size(); }
  const Point_lines& vertex_lines(std::size_t v) const { return w.vertex_lines[v]; }
  std::size_t number_of_edges() const { return w.edges.size(); }
  std::array<std::size_t, 3> edge(std::size_t e) const { return {{w.edges[e][0], w.edges[e][1], w.edges[e][2]}}; }
};

// The working form of `partition`: its lines (no line frozen, no members), points and edges in
// the same order.
template <class GeomTraits>
Working_partition working_partition(const Line_partition_2<GeomTraits>& partition)
{
  Working_partition w;
  for(const auto& l : partition.lines()) {
    Line_state state;
    state.coefficients = l.coefficients;
    state.metric = l.metric;
    state.number_of_segments = l.number_of_segments;
    state.is_fixed = l.is_fixed;
    w.lines.push_back(state);
  }
  for(const auto& v : partition.vertices())
    w.vertex_lines.emplace_back(v.lines.begin(), v.lines.end());
  for(const auto& e : partition.edges())
    w.edges.push_back({Index(e.line), Index(std::min(e.source, e.target)), Index(std::max(e.source, e.target))});
  return w;
}

// The `Line_partition_2` of `w` in the normalized frame `frame`, with the lines, points and edges
// in the same order, and the geometric traits `gt`.
template <class GeomTraits>
Line_partition_2<GeomTraits> line_partition(const Working_partition& w,
                                            const typename Line_partition_2<GeomTraits>::Frame& frame,
                                            const typename Line_partition_2<GeomTraits>::Geom_traits& gt)
{
  using Partition = Line_partition_2<GeomTraits>;
  std::vector<typename Partition::Line> lines;
  for(const auto& l : w.lines) {
    typename Partition::Line line;
    line.coefficients = l.coefficients;
    line.metric = l.metric;
    line.number_of_segments = l.number_of_segments;
    line.is_fixed = l.is_fixed;
    lines.push_back(line);
  }
  std::vector<typename Partition::Vertex> vertices;
  for(const auto& v : w.vertex_lines) vertices.push_back({std::vector<std::size_t>(v.begin(), v.end())});
  std::vector<typename Partition::Edge> edges;
  for(const auto& e : w.edges) edges.push_back({e[0], e[1], e[2]});
  return Partition(frame, std::move(lines), std::move(vertices), std::move(edges), gt);
}

// The number of cells of `w`, which must be valid: a valid partition is a plane graph, whose
// bounded faces follow from Euler's formula.
inline std::size_t number_of_cells(const Working_partition& w)
{
  std::vector<std::array<Index, 2>> ends;
  ends.reserve(w.edges.size());
  for(const auto& e : w.edges) ends.push_back({{e[1], e[2]}});
  return number_of_bounded_faces(w.vertex_lines.size(), ends);
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_WORKING_PARTITION_2_H

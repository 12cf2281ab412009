// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Enclosing_rectangle_2.h>
#include <CGAL/Polygon_partition_simplification/internal/build_line_partition_2.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Kernel_traits.h>

#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

template <class GeomTraits>
Line_partition_2<GeomTraits> line_partition_from_pieces(std::vector<Exact_piece>& pieces)
{
  if(pieces.empty()) throw Input_error(Input_error_code::EMPTY_INPUT, "the input has no edge");
  std::vector<std::array<double, 2>> points;
  for(const auto& p : pieces)
    for(const auto& q : {p.segment.source(), p.segment.target()})
      points.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y())});
  return build_line_partition<GeomTraits>(
    pieces, {}, frame_of<typename Line_partition_2<GeomTraits>::Frame>(enclosing_rectangle(points)));
}

// the polygon type of the boundaries of a `Polygon_2` (itself) or a `Polygon_with_holes_2`
template <class Polygon, class = void>
struct Ring_of { using type = Polygon; };
template <class Polygon>
struct Ring_of<Polygon, std::void_t<decltype(std::declval<const Polygon&>().outer_boundary())>>
{
  using type = std::decay_t<decltype(std::declval<const Polygon&>().outer_boundary())>;
};

template <class Point>
Exact_kernel::Point_2 exact_point(const Point& p, const std::string& where)
{
  using K = typename Kernel_traits<Point>::Kernel;
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
  if(!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e100 || std::abs(y) > 1e100)
    throw Input_error(Input_error_code::NON_FINITE_COORDINATE, where + " has a NaN, infinite or huge (beyond 1e100) coordinate");
  return CGAL::Cartesian_converter<K, Exact_kernel>()(p);
}

} // namespace internal

/*!
\ingroup PkgPolygonPartitionSimplificationRef

builds the line representation of the partition made by the edges of a CGAL arrangement of
segments (any `Arrangement_2` whose traits are `Arr_segment_traits_2<K>` or
`Arr_non_caching_segment_traits_2<K>`). Edges whose supporting lines are equal (exactly) share
one line; the metric of a line is accumulated from its edges. Edges that dangle (not on the
boundary of two different faces in a closed chain) are dropped, as are vertices where two
collinear edges meet.

\tparam GeomTraits the kernel of the result
\tparam Arrangement an `Arrangement_2` of segments

\throws Input_error when the arrangement has no edge (`EMPTY_INPUT`) or bounds no face (`NO_CELL`).
*/
template <class GeomTraits, class Arrangement>
Line_partition_2<GeomTraits> line_partition_from_arrangement_2(const Arrangement& arrangement)
{
  std::vector<internal::Exact_piece> pieces;
  for(auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    const std::string where = "edge " + std::to_string(pieces.size());
    pieces.push_back({internal::Exact_kernel::Segment_2(internal::exact_point(e->source()->point(), where),
                                                        internal::exact_point(e->target()->point(), where)),
                      false});
  }
  return internal::line_partition_from_pieces<GeomTraits>(pieces);
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

builds the line representation of the partition made by the edges of polygons (a building
footprint, a cadastral map): their edges are overlaid exactly (shared and crossing edges are
found), collinear edges share one line, and the cells are the faces of the overlay.
Zero-length edges (repeated vertices) are ignored.

\tparam PolygonRange a range of `CGAL::Polygon_2<K>` or `CGAL::Polygon_with_holes_2<K>`

\throws Input_error when there is no edge (`EMPTY_INPUT`), a NaN, infinite or huge (beyond 1e100)
coordinate (`NON_FINITE_COORDINATE`), or no cell (`NO_CELL`).
*/
template <class PolygonRange>
auto line_partition_from_polygons_2(const PolygonRange& polygons)
{
  using Polygon = std::decay_t<decltype(*std::begin(polygons))>; // any range, C arrays included
  using K = typename Kernel_traits<typename internal::Ring_of<Polygon>::type::Point_2>::Kernel;
  std::vector<internal::Exact_piece> pieces;
  std::size_t index = 0;
  auto add_ring = [&](const auto& ring) {
    const std::string where = "polygon " + std::to_string(index);
    for(auto e = ring.edges_begin(); e != ring.edges_end(); ++e) {
      const auto p = internal::exact_point(e->source(), where), q = internal::exact_point(e->target(), where);
      if(p != q) pieces.push_back({internal::Exact_kernel::Segment_2(p, q), false});
    }
  };
  for(const Polygon& polygon : polygons) {
    if constexpr(std::is_same_v<typename internal::Ring_of<Polygon>::type, Polygon>)
      add_ring(polygon);
    else {
      add_ring(polygon.outer_boundary());
      for(auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h) add_ring(*h);
    }
    ++index;
  }
  return internal::line_partition_from_pieces<K>(pieces);
}

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H

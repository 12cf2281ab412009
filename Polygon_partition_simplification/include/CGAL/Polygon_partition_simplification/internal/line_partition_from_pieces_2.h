// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_PARTITION_FROM_PIECES_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_PARTITION_FROM_PIECES_2_H

// The partition of line_partition_from_geometry_2.h built from exact pieces of edges (their
// collinear pieces snapped onto one line, overlaid first when they may cross), the
// collinearity named parameter, and the ring type of the input polygons.

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Enclosing_rectangle_2.h>
#include <CGAL/Polygon_partition_simplification/internal/build_line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/snap_collinear_segments_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// `collinearity` < 0 stands for the default: 1e-7 times the half-diagonal of the input;
// `overlay_first`: the pieces may cross or overlap (they are not the edges of an arrangement);
// `gt`: the geometric traits of the result, whose exact constructions kernel is `EK`.
template <class GeomTraits, class EK>
Line_partition_2<GeomTraits> line_partition_from_pieces(std::vector<Exact_piece<EK>>& pieces, double collinearity,
                                                        bool overlay_first,
                                                        const typename Line_partition_2<GeomTraits>::Geom_traits& gt)
{
  using PK = typename Line_partition_2<GeomTraits>::Geom_traits::Exact_predicates_kernel;
  if(pieces.empty()) throw Input_error(Input_error_code::EMPTY_INPUT, "the input has no edge");
  std::vector<std::array<double, 2>> points;
  for(const auto& p : pieces)
    for(const auto& q : {p.segment.source(), p.segment.target()})
      points.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y())});
  const Enclosing_rectangle_2 rectangle = enclosing_rectangle<PK>(points);
  // edges collinear up to rounding (a vertex in the middle of a straight wall at an angle) are
  // moved onto one line, as the segments of kinetic_partition_2() are; the vertices are moved,
  // so the pieces are first split where they meet (an edge given by both polygons it
  // separates is one edge, a corner of a polygon on the side of another is a vertex of both)
  if(collinearity < 0) collinearity = 1e-7 * rectangle.half_diagonal();
  if(collinearity > 0) {
    std::vector<typename EK::Segment_2> edges;
    if(overlay_first) {
      CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> overlay;
      std::vector<typename EK::Segment_2> segments;
      for(const auto& p : pieces) segments.push_back(p.segment);
      CGAL::insert(overlay, segments.begin(), segments.end());
      for(auto e = overlay.edges_begin(); e != overlay.edges_end(); ++e)
        edges.emplace_back(e->source()->point(), e->target()->point());
    } else
      for(const auto& p : pieces) edges.push_back(p.segment);
    if(snap_collinear_edges<EK>(edges, collinearity) > 0) {
      pieces.clear();
      for(const auto& e : edges) pieces.push_back({e, false});
    }
  }
  return build_line_partition<GeomTraits>(pieces, {}, frame_of<typename Line_partition_2<GeomTraits>::Frame>(rectangle), gt);
}

template <class NamedParameters>
double collinearity_parameter(const NamedParameters& np)
{
  constexpr bool is_default =
    parameters::is_default_parameter<NamedParameters, internal_np::collinearity_distance_t>::value;
  if(is_default) return -1;
  const double d = parameters::choose_parameter(parameters::get_parameter(np, internal_np::collinearity_distance), 0.);
  if(!(d >= 0 && std::isfinite(d)))
    throw Input_error(Input_error_code::INVALID_PARAMETER, "collinearity_distance must be finite and >= 0");
  return d;
}

// the polygon type of the boundaries of a `Polygon_2` (itself) or a `Polygon_with_holes_2`
template <class Polygon, class = void>
struct Ring_of { using type = Polygon; };
template <class Polygon>
struct Ring_of<Polygon, std::void_t<decltype(std::declval<const Polygon&>().outer_boundary())>>
{
  using type = std::decay_t<decltype(std::declval<const Polygon&>().outer_boundary())>;
};

// `p` in `EK`, the exact constructions kernel of the geometric traits, converted exactly from
// the kernel of `p`.
template <class EK, class Point>
typename EK::Point_2 exact_point(const Point& p, const std::string& where)
{
  using K = typename Kernel_traits<Point>::Kernel;
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
  if(!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e100 || std::abs(y) > 1e100)
    throw Input_error(Input_error_code::NON_FINITE_COORDINATE, where + " has a NaN, infinite or huge (beyond 1e100) coordinate");
  return CGAL::Cartesian_converter<K, EK>()(p);
}

// The partition that line_partition_from_polygons_2() returns for `PolygonRange` and
// `NamedParameters`: `Line_partition_2<Given>`, `Given` the type of `geom_traits`, or else the
// kernel of the polygons.
template <class PolygonRange, class NamedParameters>
struct Result_of_polygons
{
  using Polygon = std::decay_t<decltype(*std::begin(std::declval<const PolygonRange&>()))>;
  using Point = typename Ring_of<Polygon>::type::Point_2;
  using Given = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                                   typename Kernel_traits<Point>::Kernel>::type;
  using type = Line_partition_2<Given>;
};

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_LINE_PARTITION_FROM_PIECES_2_H

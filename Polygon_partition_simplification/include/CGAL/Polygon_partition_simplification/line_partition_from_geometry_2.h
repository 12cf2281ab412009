// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_check.h>
#include <CGAL/Polygon_partition_simplification/internal/line_partition_from_pieces_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
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
/*!
\ingroup PkgPolygonPartitionSimplificationRef

builds the line representation of the partition made by the edges of a CGAL arrangement of
segments (any `Arrangement_2` whose traits are `Arr_segment_traits_2<K>` or
`Arr_non_caching_segment_traits_2<K>`). Edges whose supporting lines are equal (exactly) share
one line; the metric of a line is accumulated from its edges. Edges that dangle (not on the
boundary of two different faces in a closed chain) are dropped, as are vertices where two
collinear edges meet.

Edges collinear only up to rounding (a straight side at an angle with a vertex in its middle:
its pieces are not exactly on one line in double precision) are put on one line first, as
`kinetic_partition_2()` does with segments: a vertex is moved onto the line of the longest edge
of the group of the edges it bounds (or to the intersection of two such lines, within 4
`collinearity_distance` of it), with exact constructions, so that rings keep their shared
vertices; where it cannot be, the groups of the longest edges are kept and the edges of the
others keep their own lines. Without this, the points of the partition, computed in double
from nearly identical lines, could make it invalid (a rotated rectangle with a vertex in the
middle of a side can be enough).

The vertices are converted exactly (`Cartesian_converter`) to the `Exact_constructions_kernel`
of the geometric traits, which gives the exact constructions; the arrangement may be in another
kernel than the result.

\tparam GeomTraits the geometric traits of the result: a model of
`PolygonPartitionSimplificationTraits_2`, or a CGAL kernel `K`, which stands for
`Polygon_partition_simplification_traits_2<K>` (see `Line_partition_2`)
\tparam Arrangement an `Arrangement_2` of segments
\tparam NamedParameters a sequence of named parameters

\cgalNamedParamsBegin
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of the geometric traits}
    \cgalParamType{`Line_partition_2<GeomTraits>::Geom_traits`}
    \cgalParamDefault{a default-constructed one}
  \cgalParamNEnd
  \cgalParamNBegin{collinearity_distance}
    \cgalParamDescription{edges whose two endpoints are within this distance of the line of a
                          longer edge are put on that line, by moving their vertices (input
                          units); 0 keeps the edges as they are (only exactly collinear edges then
                          share a line)}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$10^{-7}\f$ times the half-diagonal of the smallest enclosing rectangle
                      of the edges}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Input_error when the arrangement has no edge (`EMPTY_INPUT`), bounds no face (`NO_CELL`) or
when `collinearity_distance` is negative or not finite (`INVALID_PARAMETER`).
*/
template <class GeomTraits, class Arrangement, class NamedParameters = parameters::Default_named_parameters>
Line_partition_2<GeomTraits> line_partition_from_arrangement_2(const Arrangement& arrangement,
                                                              const NamedParameters& np = parameters::default_values())
{
  using Geom_traits = typename Line_partition_2<GeomTraits>::Geom_traits;
  using EK = typename Geom_traits::Exact_constructions_kernel;
  const Geom_traits gt =
    parameters::choose_parameter<Geom_traits>(parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  const double collinearity = internal::collinearity_parameter(np);
  std::vector<internal::Exact_piece<EK>> pieces;
  for(auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    const std::string where = "edge " + std::to_string(pieces.size());
    pieces.push_back({typename EK::Segment_2(internal::exact_point<EK>(e->source()->point(), where),
                                             internal::exact_point<EK>(e->target()->point(), where)),
                      false});
  }
  return internal::line_partition_from_pieces<GeomTraits>(pieces, collinearity, false, gt);
}

/*!
\ingroup PkgPolygonPartitionSimplificationRef

builds the line representation of the partition made by the edges of polygons (a building
footprint, a cadastral map): their edges are overlaid exactly (shared and crossing edges are
found), collinear edges share one line, and the cells are the faces of the overlay.
Zero-length edges (repeated vertices) are ignored. Edges collinear up to rounding are put on one
line as in `line_partition_from_arrangement_2()`, after the overlay (so that an edge given by
the two polygons it separates, or a corner lying on the side of another polygon, moves as one).

The vertices are converted exactly (`Cartesian_converter`) to the `Exact_constructions_kernel`
of the geometric traits, which gives the exact constructions of the overlay and of the
snapping; the kernel `K` of the polygons may have inexact predicates.

\tparam PolygonRange a range of `CGAL::Polygon_2<K>` or `CGAL::Polygon_with_holes_2<K>`
\tparam NamedParameters a sequence of named parameters

\cgalNamedParamsBegin
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of the geometric traits of the result}
    \cgalParamType{a model of `PolygonPartitionSimplificationTraits_2`, or a CGAL kernel, which
                    stands for `Polygon_partition_simplification_traits_2` of it}
    \cgalParamDefault{`Polygon_partition_simplification_traits_2<K>`}
  \cgalParamNEnd
  \cgalParamNBegin{collinearity_distance}
    \cgalParamDescription{edges whose two endpoints are within this distance of the line of a
                          longer edge are put on that line, by moving their vertices (input
                          units); 0 keeps the edges as they are (only exactly collinear edges then
                          share a line)}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$10^{-7}\f$ times the half-diagonal of the smallest enclosing rectangle
                      of the edges}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return a `Line_partition_2<GT>`, with `GT` the type of `geom_traits`, or `K` by default

\throws Input_error when there is no edge (`EMPTY_INPUT`), a NaN, infinite or huge (beyond 1e100)
coordinate (`NON_FINITE_COORDINATE`), no cell (`NO_CELL`), or a negative or infinite
`collinearity_distance` (`INVALID_PARAMETER`).
*/
template <class PolygonRange, class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Line_partition_2<GT>
#else
typename internal::Result_of_polygons<PolygonRange, NamedParameters>::type
#endif
line_partition_from_polygons_2(const PolygonRange& polygons, const NamedParameters& np = parameters::default_values())
{
  using Result = internal::Result_of_polygons<PolygonRange, NamedParameters>;
  using Polygon = typename Result::Polygon; // any range, C arrays included
  using Geom_traits = typename Result::type::Geom_traits;
  using EK = typename Geom_traits::Exact_constructions_kernel;
  const Geom_traits gt =
    parameters::choose_parameter<Geom_traits>(parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  const double collinearity = internal::collinearity_parameter(np);
  std::vector<internal::Exact_piece<EK>> pieces;
  std::size_t index = 0;
  auto add_ring = [&](const auto& ring) {
    const std::string where = "polygon " + std::to_string(index);
    for(auto e = ring.edges_begin(); e != ring.edges_end(); ++e) {
      const auto p = internal::exact_point<EK>(e->source(), where), q = internal::exact_point<EK>(e->target(), where);
      if(p != q) pieces.push_back({typename EK::Segment_2(p, q), false});
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
  return internal::line_partition_from_pieces<typename Result::Given>(pieces, collinearity, true, gt);
}

} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_LINE_PARTITION_FROM_GEOMETRY_2_H

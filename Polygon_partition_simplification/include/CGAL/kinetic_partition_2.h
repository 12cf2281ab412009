// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_KINETIC_PARTITION_2_H
#define CGAL_KINETIC_PARTITION_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Kinetic_partition_report.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/compute_kinetic_partition_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {

/*!
\ingroup PkgPolygonPartitionSimplificationRef

computes the kinetic partition of a set of 2D segments (section 3.2.2 of the thesis) inside
a rectangle around them, and returns it in line representation.

Every segment grows from both ends at unit speed. When a growing end reaches another segment
(its initial part or the part it has grown so far), it stops there if it arrives last; when
both arrive at the same time, the end of the segment that comes later in the lexicographic
order of the segments (by their smaller, then larger endpoint, exactly) stops, so the result
does not depend on the order of the input. Growing
ends stop at the rectangle, which is the smallest-area rectangle enclosing the segments, with
each side moved outward by a margin (so the partition moves with the input under rigid
motions and scalings). Intersection points and arrival times are computed exactly and
events are processed in exact time order, so the result is the exact kinetic partition of
the input coordinates.

Segments given twice (in either orientation) and collinear segments that overlap (share more
than a point, after the snapping below) are merged: their union grows as one segment, and the
fidelity metric of their line counts each of them. The named parameter `report` tells how many
were merged.

The partition's lines are the supporting lines of the segments (exactly collinear segments
share one) and the four sides of the rectangle (marked `is_fixed`); the fidelity metric of a
line is accumulated from the input segments on it (Eq. 3.5). Segments that are collinear
only up to rounding (a straight wall at an angle given in several pieces: its vertices are
not exactly on one line in double precision) are first moved onto one line, that of the
longest of them, with exact constructions: a segment whose two endpoints are within
`collinearity_distance` of the line of a longer segment is projected onto it. Without this,
the points of the partition, computed in double from nearly identical lines, could make it
invalid (one such wall can be enough).

The exact constructions (intersection points, arrival times, the projections of the
snapping, the arrangement of the extents) are those of the `Exact_constructions_kernel` of the
geometric traits; the decisions on the double points of the partition are taken with the
predicates of its `Exact_predicates_kernel` (see `PolygonPartitionSimplificationTraits_2`). The
coordinates of the segments are read as doubles (the nearest double of an exact coordinate), so
the user-facing kernel `K` may have inexact predicates (`Simple_cartesian<double>`) or exact
constructions (`Exact_predicates_exact_constructions_kernel`): the result is the same.

\tparam SegmentRange a range of `Segment_2` of a CGAL kernel `K` (of the geometric traits, when
`geom_traits` is given)
\tparam NamedParameters a sequence of named parameters

\param segments the input segments
\param np optional named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `PolygonPartitionSimplificationTraits_2`, or a CGAL kernel `K`,
                    which stands for `Polygon_partition_simplification_traits_2<K>`}
    \cgalParamDefault{`Polygon_partition_simplification_traits_2<K>`, `K` the kernel of the
                      segments (`Kernel_traits`)}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_crossings}
    \cgalParamDescription{number of segments a growing end may cross before the next one
                          stops it (`Polygon_partition_simplification::parameters`)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{crossing_distance}
    \cgalParamDescription{a growing end crosses a segment instead of stopping at it when its
                          next intersection is closer than this length (input units); this
                          makes the connectivity of the partition less sensitive to small
                          perturbations of the segments; 0 disables it}
    \cgalParamType{`double`}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{collinearity_distance}
    \cgalParamDescription{segments whose two endpoints are within this distance of the line of
                          a longer segment are moved onto that line (input units); 0 keeps
                          the segments as they are (only exactly collinear segments then share
                          a line)}
    \cgalParamType{`double`}
    \cgalParamDefault{\f$10^{-7}\f$ times the half-diagonal of the smallest enclosing rectangle
                      of the segments, or 16 units in the last place of their largest coordinate
                      if that is larger}
  \cgalParamNEnd
  \cgalParamNBegin{report}
    \cgalParamDescription{a pointer to a report that is filled with what was done to the
                          segments: merged, moved, grown (`Polygon_partition_simplification::parameters`)}
    \cgalParamType{`Polygon_partition_simplification::Kinetic_partition_report*`}
    \cgalParamDefault{`nullptr` (no report)}
  \cgalParamNEnd
  \cgalParamNBegin{bounding_box_margin}
    \cgalParamDescription{margin added on each side of the enclosing rectangle, relative to its
                          half-diagonal, in [1e-6, 100]}
    \cgalParamType{`double`}
    \cgalParamDefault{0.05}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return the partition, in line representation: a `Line_partition_2<GT>`, with `GT` the type of
`geom_traits`, or `K` by default. Its points are computed in double precision from its lines;
points that would come closer than the rounding errors (in the normalized frame, or in input
coordinates) to another point they are joined to, or to an edge they do not bound, are merged
with it or put on it when the partition is built, so that features smaller than the precision
of doubles (three nearly concurrent lines, rays meeting near the center of a star) do not make
it invalid.
Ends that meet at time 0 (segments sharing an endpoint) stop each other, so that corners
stay corners. When a closed chain of such corners touches the rest of the partition at a
single point (an "X" whose two lower ends are joined by a third segment; two squares sharing
a corner), the cell around it would not be a simple polygon: one of these ends goes on from its
corner, straight into that cell, to the cell's boundary, which splits it (after the
propagation, in the exact arrangement of the extents; points that the rounding below merges
count as one point). The propagation runs once.

\throws Polygon_partition_simplification::Input_error when `segments` is empty
(`EMPTY_INPUT`), has a NaN, infinite or huge coordinate (`NON_FINITE_COORDINATE`) or a segment
of zero length or shorter than 1e-100 (`ZERO_LENGTH_SEGMENT`), or when a parameter is out of
range (`INVALID_PARAMETER`).
*/
template <class SegmentRange,
          class NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Polygon_partition_simplification::Line_partition_2<GT>
#else
typename Polygon_partition_simplification::internal::Result_of_segments<SegmentRange, NamedParameters>::type
#endif
kinetic_partition_2(const SegmentRange& segments,
                    const NamedParameters& np = parameters::default_values())
{
  return Polygon_partition_simplification::internal::compute_kinetic_partition(segments, np);
}

} // namespace CGAL

#endif // CGAL_KINETIC_PARTITION_2_H

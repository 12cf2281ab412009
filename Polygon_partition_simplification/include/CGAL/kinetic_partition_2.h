// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_KINETIC_PARTITION_2_H
#define CGAL_KINETIC_PARTITION_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Kinetic_partition_report.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Enclosing_rectangle_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_check.h>
#include <CGAL/Polygon_partition_simplification/internal/Kinetic_propagation_2.h>
#include <CGAL/Polygon_partition_simplification/internal/build_line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/release_hanging_corners_2.h>
#include <CGAL/Polygon_partition_simplification/internal/snap_collinear_segments_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_partition_simplification {
namespace internal {

// The partition that kinetic_partition_2() returns for `SegmentRange` and `NamedParameters`:
// `Line_partition_2<Given>`, `Given` the type of `geom_traits`, or else the kernel of the segments.
template <class SegmentRange, class NamedParameters>
struct Result_of_segments
{
  using Segment = std::decay_t<decltype(*std::begin(std::declval<const SegmentRange&>()))>;
  using Given = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                                   typename Kernel_traits<Segment>::Kernel>::type;
  using type = Line_partition_2<Given>;
};

// The nearest doubles of the endpoints of `segments` (x0, y0, x1, y1 each), checked: an
// Input_error says which segment is wrong. Nothing is modified.
template <class SegmentRange, class GeomTraits>
std::vector<std::array<double, 4>> checked_segments(const SegmentRange& segments, const GeomTraits& gt)
{
  const auto source = gt.construct_source_2_object();
  const auto target = gt.construct_target_2_object();
  const auto x_of = gt.compute_x_2_object();
  const auto y_of = gt.compute_y_2_object();
  std::vector<std::array<double, 4>> input;
  for(const auto& s : segments) {
    const std::array<double, 4> c{double_of(x_of(source(s))), double_of(y_of(source(s))),
                                  double_of(x_of(target(s))), double_of(y_of(target(s)))};
    const std::string which = "segment " + std::to_string(input.size());
    for(double x : c)
      if(!std::isfinite(x) || std::abs(x) > 1e100)
        throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                          which + " has a NaN, infinite or huge (beyond 1e100) coordinate");
    if(c[0] == c[2] && c[1] == c[3])
      throw Input_error(Input_error_code::ZERO_LENGTH_SEGMENT, which + " has zero length; remove it");
    const double dx = c[2] - c[0], dy = c[3] - c[1];
    if(!(dx * dx + dy * dy >= 1e-200))
      throw Input_error(Input_error_code::ZERO_LENGTH_SEGMENT,
                        which + " is too short (below 1e-100) for double precision; scale the input");
    input.push_back(c);
  }
  if(input.empty()) throw Input_error(Input_error_code::EMPTY_INPUT, "no segment was given");
  return input;
}

// The number of segments of `input` equal to another one (either way round).
inline std::size_t number_of_equal_segments(const std::vector<std::array<double, 4>>& input)
{
  std::vector<std::array<double, 4>> sorted;
  sorted.reserve(input.size());
  for(std::array<double, 4> c : input) {
    if(std::make_pair(c[2], c[3]) < std::make_pair(c[0], c[1])) c = {c[2], c[3], c[0], c[1]};
    sorted.push_back(c);
  }
  std::sort(sorted.begin(), sorted.end());
  return std::size_t(sorted.end() - std::unique(sorted.begin(), sorted.end()));
}

} // namespace internal
} // namespace Polygon_partition_simplification

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
a corner), the cell around it would not be a simple polygon: the partition is then computed
again with one or a few of these ends released, each going on from its corner, until it is
valid (at most 16 propagations in all); when none of these is valid, the first partition is
returned, and it is not valid (`Line_partition_2::is_valid()` says so, and
`simplify_polygon_partition_2()` refuses it).

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
  namespace PPS = Polygon_partition_simplification;
  using Segment = std::decay_t<decltype(*std::begin(segments))>; // any range, C arrays included
  using Result = PPS::internal::Result_of_segments<SegmentRange, NamedParameters>;
  using Partition = typename Result::type;
  using Geom_traits = typename Partition::Geom_traits;
  static_assert(PPS::internal::Is_input_of_geom_traits<Segment, typename Geom_traits::Segment_2>::value, "");
  using EK = typename Geom_traits::Exact_constructions_kernel;
  using PK = typename Geom_traits::Exact_predicates_kernel;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using PPS::Input_error;
  using PPS::Input_error_code;
  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, internal_np::geom_traits));

  const std::size_t maximum_crossings = choose_parameter(
    get_parameter(np, PPS::internal_np::maximum_number_of_crossings), std::size_t(0));
  const double crossing_distance =
    choose_parameter(get_parameter(np, PPS::internal_np::crossing_distance), 0.);
  const double margin =
    choose_parameter(get_parameter(np, PPS::internal_np::bounding_box_margin), 0.05);
  if(!(crossing_distance >= 0) || !(margin >= 1e-6 && margin <= 100) || !std::isfinite(crossing_distance))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "crossing_distance must be finite and >= 0, bounding_box_margin in [1e-6, 100]");
  constexpr bool default_collinearity =
    parameters::is_default_parameter<NamedParameters, PPS::internal_np::collinearity_distance_t>::value;
  double collinearity = choose_parameter(get_parameter(np, PPS::internal_np::collinearity_distance), 0.);
  if(!default_collinearity && !(collinearity >= 0 && std::isfinite(collinearity)))
    throw Input_error(Input_error_code::INVALID_PARAMETER, "collinearity_distance must be finite and >= 0");

  const std::vector<std::array<double, 4>> input = PPS::internal::checked_segments(segments, gt);
  Polygon_partition_simplification::Kinetic_partition_report report;
  report.segments = input.size();
  report.equal_segments = PPS::internal::number_of_equal_segments(input);

  std::vector<std::array<double, 2>> endpoints;
  for(const auto& c : input) { endpoints.push_back({c[0], c[1]}); endpoints.push_back({c[2], c[3]}); }
  const PPS::internal::Enclosing_rectangle_2 rectangle = PPS::internal::enclosing_rectangle<PK>(endpoints);
  const double half_diagonal = rectangle.half_diagonal();
  // corners away from the lines of the segments (see corners_off_lines())
  const auto [corners, margin_across] = PPS::internal::corners_off_lines<PK>(rectangle, margin * half_diagonal, input);
  std::array<typename EK::Point_2, 4> box;
  for(int k = 0; k < 4; ++k) box[k] = typename EK::Point_2(corners[k][0], corners[k][1]);

  if(default_collinearity) {
    // 1e-7 half-diagonals, or 16 units in the last place of the coordinates if larger (lines
    // closer than that are not told apart by the input coordinates anyway)
    double largest = 0;
    for(const auto& c : input)
      for(double x : c) largest = std::max(largest, std::abs(x));
    collinearity = std::max(1e-7 * half_diagonal, 16 * (std::nextafter(largest, HUGE_VAL) - largest));
  }
  // every segment is on the line of its group's reference segment, given by its two double
  // endpoints (which spares the exact evaluation of the extents' ends to identify lines)
  const std::vector<std::size_t> reference = PPS::internal::collinear_groups(input, collinearity);
  const std::vector<typename EK::Segment_2> exact_segments = PPS::internal::snap_collinear_segments<EK>(input, reference);
  std::vector<PPS::internal::Exact_piece<EK>> metric_segments;
  for(std::size_t i = 0; i < input.size(); ++i) metric_segments.push_back({exact_segments[i], false, reference[i]});
  for(std::size_t i = 0; i < input.size(); ++i) report.moved_segments += reference[i] != i ? 1 : 0;
  // the propagation grows distinct segments, equal and overlapping collinear ones merged (two
  // moved onto one line can coincide too; the metric of their line counts each), in an order
  // that does not depend on the input's
  std::size_t merged = 0;
  const std::vector<std::pair<typename EK::Segment_2, std::size_t>> distinct = // with the group
    PPS::internal::merge_overlapping_segments<EK>(exact_segments, reference, merged);
  report.overlapping_segments = merged > report.equal_segments ? merged - report.equal_segments : 0;
  report.grown_segments = distinct.size();
  std::vector<typename EK::Segment_2> distinct_segments;
  for(const auto& d : distinct) distinct_segments.push_back(d.first);

  PPS::internal::Enclosing_rectangle_2 framed = rectangle;
  framed.half_extent = {rectangle.half_extent[0] + margin * half_diagonal,
                        rectangle.half_extent[1] + margin_across};
  const auto frame = PPS::internal::frame_of<typename Partition::Frame>(framed);

  // The partition of a propagation that has run: the extents and the sides of the rectangle.
  auto partition_of = [&](const PPS::internal::Kinetic_propagation_2<EK>& propagation) {
    std::vector<PPS::internal::Exact_piece<EK>> pieces;
    pieces.reserve(distinct.size() + 4);
    for(std::size_t i = 0; i < distinct.size(); ++i) pieces.push_back({propagation.extent(i), false, distinct[i].second});
    for(int k = 0; k < 4; ++k) pieces.push_back({typename EK::Segment_2(box[k], box[(k + 1) % 4]), true});
    report.events = propagation.statistics().events;
    return PPS::internal::build_line_partition<typename Result::Given>(pieces, metric_segments, frame, gt, input);
  };
  auto make_propagation = [&] {
    return PPS::internal::Kinetic_propagation_2<EK>(distinct_segments, box, maximum_crossings, crossing_distance);
  };
  // again with some corners released while a chain of corners hangs at a point (see
  // release_hanging_corners_2.h)
  Partition result =
    PPS::internal::propagate_releasing_hanging_corners(make_propagation, partition_of, 1e-9 * frame.scale, report.propagations);
  if(auto* out = choose_parameter(get_parameter(np, PPS::internal_np::report), static_cast<PPS::Kinetic_partition_report*>(nullptr)))
    *out = report;
  return result;
}

} // namespace CGAL

#endif // CGAL_KINETIC_PARTITION_2_H

// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_KINETIC_PARTITION_2_H
#define CGAL_KINETIC_PARTITION_2_H

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
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
                      of the segments}
  \cgalParamNEnd
  \cgalParamNBegin{bounding_box_margin}
    \cgalParamDescription{margin added on each side of the enclosing rectangle, relative to its
                          half-diagonal, in [1e-6, 100]}
    \cgalParamType{`double`}
    \cgalParamDefault{0.05}
  \cgalParamNEnd
\cgalNamedParamsEnd

\return the partition, in line representation: a `Line_partition_2<GT>`, with `GT` the type of
`geom_traits`, or `K` by default. Its points are computed in double precision
from its lines: two exact intersection points closer than the precision of doubles (segments
on nearly identical lines farther apart than `collinearity_distance` that cross) can get the
same coordinates, and the partition is then not valid (`Line_partition_2::is_valid()` says
so, and `simplify_polygon_partition_2()` refuses it).
Ends that meet at time 0 (segments sharing an endpoint) stop each other, so that corners
stay corners. When a closed chain of such corners touches the rest of the partition at a
single point (an "X" whose two lower ends are joined by a third segment; two squares sharing
a corner), the cell around it would not be a simple polygon: the partition is then computed
again with one or a few of these ends released, each going on from its corner, until it is
valid (at most 16 propagations in all); when none of these is valid, the first partition is
returned, and it is not valid.

\throws Polygon_partition_simplification::Input_error when `segments` is empty
(`EMPTY_INPUT`), has a NaN, infinite or huge coordinate (`NON_FINITE_COORDINATE`), a segment
of zero length or shorter than 1e-100 (`ZERO_LENGTH_SEGMENT`) or twice the same segment
(`DUPLICATED_SEGMENT`), or when a parameter is out of range (`INVALID_PARAMETER`).
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
  const auto source = gt.construct_source_2_object();
  const auto target = gt.construct_target_2_object();
  const auto x_of = gt.compute_x_2_object();
  const auto y_of = gt.compute_y_2_object();

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

  // Checks: nothing is modified, an error says which segment is wrong.
  std::vector<std::array<double, 4>> input;
  for(const Segment& s : segments) {
    // the nearest doubles (a double as it is)
    const std::array<double, 4> c{PPS::internal::double_of(x_of(source(s))), PPS::internal::double_of(y_of(source(s))),
                                  PPS::internal::double_of(x_of(target(s))), PPS::internal::double_of(y_of(target(s)))};
    const std::string which = "segment " + std::to_string(input.size());
    for(double x : c)
      if(!std::isfinite(x) || std::abs(x) > 1e100)
        throw Input_error(Input_error_code::NON_FINITE_COORDINATE,
                          which + " has a NaN, infinite or huge (beyond 1e100) coordinate");
    if(c[0] == c[2] && c[1] == c[3])
      throw Input_error(Input_error_code::ZERO_LENGTH_SEGMENT,
                        which + " has zero length; remove it");
    const double dx = c[2] - c[0], dy = c[3] - c[1];
    if(!(dx * dx + dy * dy >= 1e-200))
      throw Input_error(Input_error_code::ZERO_LENGTH_SEGMENT,
                        which + " is too short (below 1e-100) for double precision; scale the input");
    input.push_back(c);
  }
  if(input.empty())
    throw Input_error(Input_error_code::EMPTY_INPUT, "no segment was given");
  {
    std::vector<std::pair<std::array<double, 4>, std::size_t>> sorted;
    for(std::size_t i = 0; i < input.size(); ++i) {
      std::array<double, 4> c = input[i];
      if(std::make_pair(c[2], c[3]) < std::make_pair(c[0], c[1])) c = {c[2], c[3], c[0], c[1]};
      sorted.emplace_back(c, i);
    }
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t i = 1; i < sorted.size(); ++i)
      if(sorted[i].first == sorted[i - 1].first)
        throw Input_error(Input_error_code::DUPLICATED_SEGMENT,
                          "segments " + std::to_string(sorted[i - 1].second) + " and " +
                            std::to_string(sorted[i].second) + " are the same; remove one");
  }

  std::vector<std::array<double, 2>> endpoints;
  for(const auto& c : input) { endpoints.push_back({c[0], c[1]}); endpoints.push_back({c[2], c[3]}); }
  const PPS::internal::Enclosing_rectangle_2 rectangle = PPS::internal::enclosing_rectangle<PK>(endpoints);
  const double half_diagonal = rectangle.half_diagonal();
  // corners away from the lines of the segments (see corners_off_lines())
  const auto [corners, margin_across] = PPS::internal::corners_off_lines<PK>(rectangle, margin * half_diagonal, input);
  std::array<typename EK::Point_2, 4> box;
  for(int k = 0; k < 4; ++k) box[k] = typename EK::Point_2(corners[k][0], corners[k][1]);

  if(default_collinearity) collinearity = 1e-7 * half_diagonal;
  // every segment is on the line of its group's reference segment, given by its two double
  // endpoints (which spares the exact evaluation of the extents' ends to identify lines)
  const std::vector<std::size_t> reference = PPS::internal::collinear_groups(input, collinearity);
  const std::vector<typename EK::Segment_2> exact_segments = PPS::internal::snap_collinear_segments<EK>(input, reference);
  std::vector<PPS::internal::Exact_piece<EK>> metric_segments;
  for(std::size_t i = 0; i < input.size(); ++i) metric_segments.push_back({exact_segments[i], false, reference[i]});
  // the propagation needs distinct segments (two moved onto the same line can coincide; the
  // metric of their line counts both), in an order that does not depend on the input's
  std::vector<std::pair<typename EK::Segment_2, std::size_t>> distinct; // with the group
  {
    auto canonical = [](const typename EK::Segment_2& s) {
      return CGAL::compare_xy(s.source(), s.target()) == CGAL::LARGER ? s.opposite() : s;
    };
    for(std::size_t i = 0; i < input.size(); ++i) distinct.emplace_back(canonical(exact_segments[i]), reference[i]);
    auto less = [](const auto& a, const auto& b) {
      const CGAL::Comparison_result c = CGAL::compare_xy(a.first.source(), b.first.source());
      return c == CGAL::SMALLER || (c == CGAL::EQUAL && CGAL::compare_xy(a.first.target(), b.first.target()) == CGAL::SMALLER);
    };
    std::sort(distinct.begin(), distinct.end(), less);
    distinct.erase(std::unique(distinct.begin(), distinct.end(),
                               [](const auto& a, const auto& b) { return a.first == b.first; }),
                   distinct.end());
  }
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
    return PPS::internal::build_line_partition<typename Result::Given>(pieces, metric_segments, frame, gt, input);
  };
  auto make_propagation = [&] {
    return PPS::internal::Kinetic_propagation_2<EK>(distinct_segments, box, maximum_crossings, crossing_distance);
  };
  // again with some corners released while a chain of corners hangs at a point (see
  // release_hanging_corners_2.h)
  return PPS::internal::propagate_releasing_hanging_corners(make_propagation, partition_of, 1e-9 * frame.scale);
}

} // namespace CGAL

#endif // CGAL_KINETIC_PARTITION_2_H

// Copyright (c) 2026  The Polygon_partition_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_COMPUTE_KINETIC_PARTITION_2_H
#define CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_COMPUTE_KINETIC_PARTITION_2_H

// The kinetic partition of `kinetic_partition_2()`: the input read and checked, collinear
// segments snapped onto one line and overlapping ones merged, the propagation
// (Kinetic_propagation_2.h) in the enclosing rectangle, and the partition built from its extents
// (build_line_partition_2.h), where an end stopped at a corner goes on when a chain of corners
// hangs at one point (split_pinched_cells_2.h).

#include <CGAL/license/Polygon_partition_simplification.h>

#include <CGAL/Polygon_partition_simplification/Input_error.h>
#include <CGAL/Polygon_partition_simplification/Kinetic_partition_report.h>
#include <CGAL/Polygon_partition_simplification/Line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Enclosing_rectangle_2.h>
#include <CGAL/Polygon_partition_simplification/internal/Geom_traits_check.h>
#include <CGAL/Polygon_partition_simplification/internal/Kinetic_propagation_2.h>
#include <CGAL/Polygon_partition_simplification/internal/build_line_partition_2.h>
#include <CGAL/Polygon_partition_simplification/internal/snap_collinear_segments_2.h>
#include <CGAL/Polygon_partition_simplification/parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <optional>
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

// The named parameters of `kinetic_partition_2()`, checked.
struct Kinetic_partition_settings
{
  std::size_t maximum_crossings = 0;
  double crossing_distance = 0;
  double margin = 0.05;                // of the half-diagonal of the segments' bounding rectangle
  std::optional<double> collinearity;  // none: default_collinearity_distance()
};

template <class NamedParameters>
Kinetic_partition_settings kinetic_partition_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Kinetic_partition_settings settings;
  settings.maximum_crossings = choose_parameter(get_parameter(np, internal_np::maximum_number_of_crossings), std::size_t(0));
  settings.crossing_distance = choose_parameter(get_parameter(np, internal_np::crossing_distance), 0.);
  settings.margin = choose_parameter(get_parameter(np, internal_np::bounding_box_margin), 0.05);
  if(!(settings.crossing_distance >= 0) || !std::isfinite(settings.crossing_distance) ||
     !(settings.margin >= 1e-6 && settings.margin <= 100))
    throw Input_error(Input_error_code::INVALID_PARAMETER,
                      "crossing_distance must be finite and >= 0, bounding_box_margin in [1e-6, 100]");
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::collinearity_distance_t>::value) {
    const double collinearity = get_parameter(np, internal_np::collinearity_distance);
    if(!(collinearity >= 0 && std::isfinite(collinearity)))
      throw Input_error(Input_error_code::INVALID_PARAMETER, "collinearity_distance must be finite and >= 0");
    settings.collinearity = collinearity;
  }
  return settings;
}

// 1e-7 half-diagonals, or 16 units in the last place of the coordinates of `input` if larger
// (lines closer than that are not told apart by the input coordinates anyway)
inline double default_collinearity_distance(const std::vector<std::array<double, 4>>& input, double half_diagonal)
{
  double largest = 0;
  for(const auto& c : input)
    for(double x : c) largest = std::max(largest, std::abs(x));
  return std::max(1e-7 * half_diagonal, 16 * (std::nextafter(largest, HUGE_VAL) - largest));
}

// the partition of `kinetic_partition_2(segments, np)`
template <class SegmentRange, class NamedParameters>
typename Result_of_segments<SegmentRange, NamedParameters>::type
compute_kinetic_partition(const SegmentRange& segments, const NamedParameters& np)
{
  namespace PPS = Polygon_partition_simplification;
  using Segment = std::decay_t<decltype(*std::begin(segments))>; // any range, C arrays included
  using Result = Result_of_segments<SegmentRange, NamedParameters>;
  using Partition = typename Result::type;
  using Geom_traits = typename Partition::Geom_traits;
  static_assert(Is_input_of_geom_traits<Segment, typename Geom_traits::Segment_2>::value, "");
  using EK = typename Geom_traits::Exact_constructions_kernel;
  using PK = typename Geom_traits::Exact_predicates_kernel;
  const Geom_traits gt = parameters::choose_parameter<Geom_traits>(parameters::get_parameter(np, CGAL::internal_np::geom_traits));
  const Kinetic_partition_settings settings = kinetic_partition_settings(np);

  const std::vector<std::array<double, 4>> input = PPS::internal::checked_segments(segments, gt);
  Polygon_partition_simplification::Kinetic_partition_report report;
  report.segments = input.size();
  report.equal_segments = PPS::internal::number_of_equal_segments(input);

  std::vector<std::array<double, 2>> endpoints;
  for(const auto& c : input) { endpoints.push_back({c[0], c[1]}); endpoints.push_back({c[2], c[3]}); }
  const PPS::internal::Enclosing_rectangle_2 rectangle = PPS::internal::enclosing_rectangle<PK>(endpoints);
  const double half_diagonal = rectangle.half_diagonal();
  // corners away from the lines of the segments (see corners_off_lines())
  const auto [corners, margin_across] = PPS::internal::corners_off_lines<PK>(rectangle, settings.margin * half_diagonal, input);
  std::array<typename EK::Point_2, 4> box;
  for(int k = 0; k < 4; ++k) box[k] = typename EK::Point_2(corners[k][0], corners[k][1]);

  const double collinearity =
    settings.collinearity ? *settings.collinearity : default_collinearity_distance(input, half_diagonal);
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
  framed.half_extent = {rectangle.half_extent[0] + settings.margin * half_diagonal,
                        rectangle.half_extent[1] + margin_across};
  const auto frame = PPS::internal::frame_of<typename Partition::Frame>(framed);

  // The propagation, and the partition of its extents and the sides of the rectangle, with the
  // ends stopped at their corners at time 0 offered to split the cells that are not simple
  // polygons (see split_pinched_cells_2.h).
  PPS::internal::Kinetic_propagation_2<EK> propagation(distinct_segments, box, settings.maximum_crossings,
                                                       settings.crossing_distance);
  propagation.run();
  report.events = propagation.statistics().events;
  std::vector<PPS::internal::Exact_piece<EK>> pieces;
  pieces.reserve(distinct.size() + 4);
  for(std::size_t i = 0; i < distinct.size(); ++i) pieces.push_back({propagation.extent(i), false, distinct[i].second});
  for(int k = 0; k < 4; ++k) pieces.push_back({typename EK::Segment_2(box[k], box[(k + 1) % 4]), true});
  std::vector<PPS::internal::Corner_ray<EK>> corner_rays;
  for(std::size_t r = 0; r < propagation.number_of_rays(); ++r)
    if(propagation.stopped_at_origin(r)) corner_rays.push_back({propagation.origin(r), propagation.direction(r), r / 2});
  Partition result = PPS::internal::build_line_partition<typename Result::Given>(
    pieces, metric_segments, frame, gt, input, corner_rays, &report.extended_corner_ends, &report.removed_edges);
  if(auto* out = parameters::choose_parameter(parameters::get_parameter(np, PPS::internal_np::report), static_cast<PPS::Kinetic_partition_report*>(nullptr)))
    *out = report;
  return result;
}

} // namespace internal
} // namespace Polygon_partition_simplification
} // namespace CGAL

#endif // CGAL_POLYGON_PARTITION_SIMPLIFICATION_INTERNAL_COMPUTE_KINETIC_PARTITION_2_H
